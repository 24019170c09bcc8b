// Image files: EXR through OpenEXR, PNG and HDR through stb_image / stb_image_write.

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <ImathBox.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>

#include "exr_input.hpp"
#include "gfield/atomic_file.hpp"
#include "gfield/file_extension.hpp"
#include "gfield/file_read.hpp"
#include "gfield/image.hpp"
#include "gfield/limits.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

/// stb_image's reason for its last failure, printable on one line: for an unknown PNG chunk it
/// holds the chunk's four bytes, whatever they are.
std::string stb_failure() {
  return printable(stbi_failure_reason());
}

/// Pictures of at most kMaxPictureSide per side and kMaxPicturePixels in all.
bool check_pixel_count(const std::string& filename, int width, int height, std::string& error) {
  if (width < 1 || height < 1 || width > kMaxPictureSide || height > kMaxPictureSide ||
      std::int64_t(width) * height > kMaxPicturePixels) {
    error = filename + ": " + std::to_string(width) + "x" + std::to_string(height) +
            " pixels, more than the limit of " + std::to_string(kMaxPicturePixels) + " (" +
            std::to_string(kMaxPictureSide) + " per side)";
    return false;
  }
  return true;
}

/// The data window's size of an EXR picture, checked as load_exr checks it.
bool exr_size(const std::string& filename, int& width, int& height, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  if (!open_exr_input(filename, kMaxPictureSide, kMaxPictureSide, {"R", "G", "B", "Y"}, file,
                      error)) {
    return false;
  }
  const Imath::Box2i window = file->header().dataWindow();
  width = window.max.x - window.min.x + 1;
  height = window.max.y - window.min.y + 1;
  return check_pixel_count(filename, width, height, error);
}

bool load_exr(const std::string& filename, Image& image, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  if (!open_exr_input(filename, kMaxPictureSide, kMaxPictureSide, {"R", "G", "B", "Y"}, file,
                      error)) {
    return false;
  }
  try {
    const Imath::Box2i window = file->header().dataWindow();
    const int width = window.max.x - window.min.x + 1;
    const int height = window.max.y - window.min.y + 1;
    const Imf::ChannelList& channels = file->header().channels();
    const bool rgb =
        channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    const bool grey = channels.findChannel("Y") != nullptr;
    if (!rgb && !grey) {
      error = filename + ": EXR has neither R, G, B nor Y channels";
      return false;
    }
    if (!check_pixel_count(filename, width, height, error)) {
      return false;
    }
    Image result(width, height);
    const size_t xstride = sizeof(glm::vec3);
    const size_t ystride = sizeof(glm::vec3) * size_t(width);
    // OpenEXR addresses pixel (x, y) of the data window as base + x * xstride + y * ystride.
    char* base = reinterpret_cast<char*>(result.pixels.data()) -
                 std::ptrdiff_t(window.min.x) * std::ptrdiff_t(xstride) -
                 std::ptrdiff_t(window.min.y) * std::ptrdiff_t(ystride);
    Imf::FrameBuffer frame;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
      frame.insert(rgb ? names[c] : "Y",
                   Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xstride, ystride));
    }
    file->setFrameBuffer(frame);
    file->readPixels(window.min.y, window.max.y);
    image = std::move(result);
    return true;
  } catch (const std::exception& e) {
    error = filename + ": cannot read EXR: " + exr_exception_text(e);
    return false;
  }
}

/// The fewest bytes a file of the format of `bytes` can hold a width x height picture in: a PNG
/// at 1 bit per pixel (plus a filter byte per row) deflated at zlib's best ratio; a JPEG at 2
/// bits per 8x8 block (its shortest DC and end-of-block codes); anything else (HDR) at 3 bytes
/// per pixel, compressed at kMaxCompressionRatio.
std::uint64_t min_file_bytes(const stbi_uc* bytes, int size, int width, int height) {
  const auto w = std::uint64_t(width), h = std::uint64_t(height);
  if (size >= 8 && std::memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0)
    return h * ((w + 7) / 8 + 1) / kMaxCompressionRatio;
  if (size >= 2 && bytes[0] == 0xFF && bytes[1] == 0xD8)
    return ((w + 7) / 8) * ((h + 7) / 8) / 4;
  return w * h * 3 / kMaxCompressionRatio;
}

std::uint32_t big_endian(const stbi_uc* bytes, int count) {
  std::uint32_t value = 0;
  for (int k = 0; k < count; ++k)
    value = value << 8 | bytes[k];
  return value;
}

/// The size a PNG's IHDR or a JPEG's frame header claims, read here because stb_image refuses a
/// picture beyond its own size limit in its header check as an "unknown image type". False for
/// other data (and for a JPEG without a frame header before its scan).
bool png_or_jpeg_size(const stbi_uc* bytes, int size, int& width, int& height) {
  if (size >= 24 && std::memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0 &&
      std::memcmp(bytes + 12, "IHDR", 4) == 0) {
    width = int(std::min<std::uint32_t>(big_endian(bytes + 16, 4), 0x7FFFFFFFu));
    height = int(std::min<std::uint32_t>(big_endian(bytes + 20, 4), 0x7FFFFFFFu));
    return true;
  }
  if (size < 4 || bytes[0] != 0xFF || bytes[1] != 0xD8)
    return false;
  // Segments: 0xFF, a marker, a 2-byte length counting itself (none for RSTn, SOI, TEM).
  for (int i = 2; i + 3 < size;) {
    if (bytes[i] != 0xFF)
      return false;
    const stbi_uc marker = bytes[i + 1];
    if (marker == 0xFF || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8)) {
      i += marker == 0xFF ? 1 : 2;  // fill byte, or a marker without a length
      continue;
    }
    if (marker == 0xDA || marker == 0xD9)  // the scan (or the end) before any frame header
      return false;
    const bool frame =
        marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (frame && i + 9 <= size) {
      height = int(big_endian(bytes + i + 5, 2));
      width = int(big_endian(bytes + i + 7, 2));
      return true;
    }
    i += 2 + int(big_endian(bytes + i + 2, 2));
  }
  return false;
}

/// Checks what a PNG, JPEG or HDR header claims against the limits and the data's size before
/// stb_image allocates for it; the size it claims in `width`, `height`.
bool check_stb_header(const std::string& name, const stbi_uc* bytes, int size, int& width,
                      int& height, std::string& error) {
  int components = 0;
  if (!png_or_jpeg_size(bytes, size, width, height) &&
      !stbi_info_from_memory(bytes, size, &width, &height, &components)) {
    error = name + ": cannot read image: " + stb_failure();
    return false;
  }
  if (!check_pixel_count(name, width, height, error)) {
    return false;
  }
  if (min_file_bytes(bytes, size, width, height) > std::uint64_t(size)) {
    error = name + ": header claims " + std::to_string(width) + "x" + std::to_string(height) +
            " pixels, more than the file's " + std::to_string(size) +
            " bytes can hold (truncated or corrupt)";
    return false;
  }
  return true;
}

/// Decodes a PNG, JPEG or HDR held in memory (`name` for errors): 8 and 16-bit values are sRGB,
/// converted to linear; HDR is linear already.
bool decode_stb(const std::string& name, const stbi_uc* bytes, int size, Image& image,
                std::string& error) {
  int width = 0, height = 0, components = 0;
  if (!check_stb_header(name, bytes, size, width, height, error)) {
    return false;
  }
  if (stbi_is_hdr_from_memory(bytes, size)) {
    std::unique_ptr<float, void (*)(void*)> data(
        stbi_loadf_from_memory(bytes, size, &width, &height, &components, 3), stbi_image_free);
    if (!data) {
      error = name + ": cannot read image: " + stb_failure();
      return false;
    }
    Image result(width, height);
    std::copy_n(data.get(), size_t(width) * size_t(height) * 3, &result.pixels[0].x);
    image = std::move(result);
    return true;
  }
  const bool sixteen = stbi_is_16_bit_from_memory(bytes, size);
  Image result;
  if (sixteen) {
    std::unique_ptr<stbi_us, void (*)(void*)> data(
        stbi_load_16_from_memory(bytes, size, &width, &height, &components, 3), stbi_image_free);
    if (!data) {
      error = name + ": cannot read image: " + stb_failure();
      return false;
    }
    result = Image(width, height);
    float* out = &result.pixels[0].x;
    for (size_t i = 0; i < size_t(width) * size_t(height) * 3; ++i) {
      out[i] = srgb_to_linear(float(data.get()[i]) / 65535.0f);
    }
  } else {
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes, size, &width, &height, &components, 3), stbi_image_free);
    if (!data) {
      error = name + ": cannot read image: " + stb_failure();
      return false;
    }
    float table[256];
    for (int v = 0; v < 256; ++v) {
      table[v] = srgb_to_linear(float(v) / 255.0f);
    }
    result = Image(width, height);
    float* out = &result.pixels[0].x;
    for (size_t i = 0; i < size_t(width) * size_t(height) * 3; ++i) {
      out[i] = table[data.get()[i]];
    }
  }
  image = std::move(result);
  return true;
}

/// An image file's reader, by its extension.
enum class ImageKind { kExr, kStb, kNone };

/// The reader of `filename`; kNone with `error` when it is no file or has another extension.
ImageKind image_kind(const std::string& filename, std::string& error) {
  if (const std::string problem = file_problem(filename); !problem.empty()) {
    error = filename + ": " + problem;
    return ImageKind::kNone;
  }
  const std::string ext = lower_extension(filename);
  if (ext == ".exr")
    return ImageKind::kExr;
  if (ext == ".hdr" || ext == ".png" || ext == ".jpg" || ext == ".jpeg")
    return ImageKind::kStb;
  error = filename + ": unknown image extension \"" + ext +
          "\" (expected .exr, .hdr, .png, .jpg or .jpeg)";
  return ImageKind::kNone;
}

/// Image data held in memory: 1 byte to 2 GiB (stb_image counts in int).
bool check_data_size(const std::string& name, size_t size, std::string& error) {
  if (size == 0) {
    error = name + ": empty image data";
    return false;
  }
  if (size > size_t(std::numeric_limits<int>::max())) {
    error = name + ": image data of " + std::to_string(size) + " bytes (at most 2 GiB)";
    return false;
  }
  return true;
}

bool load_stb(const std::string& filename, Image& image, std::string& error) {
  std::string data;
  if (!read_file(filename, kMaxPictureFileBytes, data, error)) {
    return false;
  }
  return decode_image(filename, reinterpret_cast<const unsigned char*>(data.data()), data.size(),
                      image, error);
}

bool save_exr(const std::string& path, const Image& image) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  const char* names[3] = {"R", "G", "B"};
  Imf::FrameBuffer frame;
  char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
  for (int c = 0; c < 3; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(glm::vec3),
                                      sizeof(glm::vec3) * size_t(image.width)));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(image.height);
  return true;
}

/// The pixels as 8-bit sRGB, clamped to [0, 1].
std::vector<std::uint8_t> srgb_bytes(const Image& image) {
  std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      bytes[i * 3 + size_t(c)] = srgb_byte(image.pixels[i][c]);
  }
  return bytes;
}

bool save_png(const std::string& path, const Image& image) {
  const std::vector<std::uint8_t> bytes = srgb_bytes(image);
  stbi_write_png_compression_level = 1;
  return stbi_write_png(path.c_str(), image.width, image.height, 3, bytes.data(),
                        image.width * 3) != 0;
}

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
}

}  // namespace

float srgb_to_linear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

float linear_to_srgb(float v) {
  return v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

std::uint8_t srgb_byte(float linear) {
  return std::uint8_t(std::lround(linear_to_srgb(std::clamp(linear, 0.0f, 1.0f)) * 255.0f));
}

glm::vec3 sample_bilinear(const Image& image, float x, float y, bool wrap_x) {
  const float fx = x - 0.5f;
  const float fy = std::clamp(y - 0.5f, 0.0f, float(image.height - 1));
  const int x0 = int(std::floor(fx));
  const int y0 = int(std::floor(fy));
  const float ax = fx - float(x0);
  const float ay = fy - float(y0);
  auto column = [&](int c) {
    if (wrap_x) {
      c %= image.width;
      return c < 0 ? c + image.width : c;
    }
    return std::clamp(c, 0, image.width - 1);
  };
  const int xa = column(x0);
  const int xb = column(x0 + 1);
  const int ya = std::clamp(y0, 0, image.height - 1);
  const int yb = std::min(ya + 1, image.height - 1);
  const glm::vec3 top = glm::mix(image.at(xa, ya), image.at(xb, ya), ax);
  const glm::vec3 bottom = glm::mix(image.at(xa, yb), image.at(xb, yb), ax);
  return glm::mix(top, bottom, ay);
}

bool load_image(const std::string& filename, Image& image, std::string& error) {
  const ImageKind kind = image_kind(filename, error);
  return kind == ImageKind::kExr   ? load_exr(filename, image, error)
         : kind == ImageKind::kStb ? load_stb(filename, image, error)
                                   : false;
}

bool load_image_size(const std::string& filename, int& width, int& height, std::string& error) {
  const ImageKind kind = image_kind(filename, error);
  if (kind == ImageKind::kExr)
    return exr_size(filename, width, height, error);
  std::string data;
  return kind == ImageKind::kStb && read_file(filename, kMaxPictureFileBytes, data, error) &&
         decode_image_size(filename, reinterpret_cast<const unsigned char*>(data.data()),
                           data.size(), width, height, error);
}

bool decode_image(const std::string& name, const unsigned char* bytes, size_t size, Image& image,
                  std::string& error) {
  return check_data_size(name, size, error) && decode_stb(name, bytes, int(size), image, error);
}

bool decode_image_size(const std::string& name, const unsigned char* bytes, size_t size, int& width,
                       int& height, std::string& error) {
  return check_data_size(name, size, error) &&
         check_stb_header(name, bytes, int(size), width, height, error);
}

bool encode_png(const Image& image, std::string& bytes) {
  const std::vector<std::uint8_t> pixels = srgb_bytes(image);
  bytes.clear();
  stbi_write_png_compression_level = 9;
  return image.width > 0 && image.height > 0 &&
         stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 3, pixels.data(),
                                image.width * 3) != 0;
}

bool save_image(const std::string& filename, const Image& image, std::string& error) {
  const std::string ext = lower_extension(filename);
  if (ext != ".exr" && ext != ".png") {
    error = filename + ": unknown image extension \"" + ext + "\" (expected .exr or .png)";
    return false;
  }
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != size_t(image.width) * size_t(image.height)) {
    error = filename + ": image has no pixels";
    return false;
  }
  TemporaryFile temporary(filename);
  bool written = false;
  errno = 0;
  try {
    written = ext == ".exr" ? save_exr(temporary.path().string(), image)
                            : save_png(temporary.path().string(), image);
  } catch (const std::exception& e) {
    error = filename + ": cannot write: " + temporary.as_target(e.what());
    return false;
  }
  if (!written) {  // stb_image_write's fopen or fwrite failed: errno says why
    error = filename + ": cannot write" +
            (errno != 0 ? " (" + std::string(std::strerror(errno)) + ")" : std::string());
    return false;
  }
  return temporary.commit(error);
}

}  // namespace gfield
