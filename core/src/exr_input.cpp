// Checks an OpenEXR header's structure by reading its bytes (docs: openexr.com, "OpenEXR File
// Layout") before OpenEXR parses it.

#include "exr_input.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

#include "gfield/file_read.hpp"
#include "gfield/limits.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

constexpr std::uint64_t kMaxHeaderBytes = 1 << 20;
constexpr std::uint32_t kTiledFlag = 0x200, kDeepFlag = 0x800, kMultipartFlag = 0x1000;

/// What the header says that the checks need.
struct ExrLayout {
  bool tiled = false;
  std::int64_t min_x = 0, min_y = 0, max_x = -1, max_y = -1;  ///< data window
  int compression = -1;
  std::uint32_t tile_x = 0, tile_y = 0;
  int tile_mode = -1;
  struct Channel {
    int type = 0;  ///< 0 UINT, 1 HALF, 2 FLOAT
    std::int32_t x_sampling = 1, y_sampling = 1;
  };
  std::map<std::string, Channel> channels;
};

/// Little-endian reads within the header bytes; false past their end.
class HeaderBytes {
 public:
  explicit HeaderBytes(const std::string& bytes) : bytes_(bytes) {}
  bool string(std::string& out) {
    const size_t end = bytes_.find('\0', position_);
    if (end == std::string::npos || end - position_ > 255) {
      return false;
    }
    out = bytes_.substr(position_, end - position_);
    position_ = end + 1;
    return true;
  }
  template <class T>
  bool value(T& out) {
    if (bytes_.size() - position_ < sizeof(T)) {
      return false;
    }
    std::memcpy(&out, bytes_.data() + position_, sizeof(T));  // x86-64 and ARM are little endian
    position_ += sizeof(T);
    return true;
  }
  bool skip(std::uint64_t n) {
    if (bytes_.size() - position_ < n) {
      return false;
    }
    position_ += size_t(n);
    return true;
  }
  size_t position() const { return position_; }

 private:
  const std::string& bytes_;
  size_t position_ = 0;
};

bool read_channels(HeaderBytes& in, size_t end, ExrLayout& layout) {
  std::string name;
  while (in.position() < end) {
    if (!in.string(name)) {
      return false;
    }
    if (name.empty()) {
      return in.position() == end;
    }
    ExrLayout::Channel c;
    std::uint8_t linear_and_reserved[4];
    if (!in.value(c.type) || !in.value(linear_and_reserved) || !in.value(c.x_sampling) ||
        !in.value(c.y_sampling) || c.type < 0 || c.type > 2 || c.x_sampling < 1 ||
        c.y_sampling < 1) {
      return false;
    }
    layout.channels[name] = c;
  }
  return false;
}

/// Bytes of the attribute types OpenEXR reads with a fixed size whatever the header's size field
/// says (it would then parse the rest of the header from the wrong place); 0 for other types.
std::uint32_t fixed_attribute_size(const std::string& type) {
  static const std::map<std::string, std::uint32_t> kSizes = {{"int", 4},
                                                              {"float", 4},
                                                              {"double", 8},
                                                              {"v2i", 8},
                                                              {"v2f", 8},
                                                              {"v2d", 16},
                                                              {"v3i", 12},
                                                              {"v3f", 12},
                                                              {"v3d", 24},
                                                              {"box2i", 16},
                                                              {"box2f", 16},
                                                              {"m33f", 36},
                                                              {"m33d", 72},
                                                              {"m44f", 64},
                                                              {"m44d", 128},
                                                              {"compression", 1},
                                                              {"lineOrder", 1},
                                                              {"envmap", 1},
                                                              {"deepImageState", 1},
                                                              {"tiledesc", 9},
                                                              {"chromaticities", 32},
                                                              {"keycode", 28},
                                                              {"timecode", 8},
                                                              {"rational", 8}};
  const auto found = kSizes.find(type);
  return found == kSizes.end() ? 0 : found->second;
}

/// A stringvector's entries (a 32-bit length, then the bytes) fill exactly `size` bytes.
bool read_string_vector(HeaderBytes& in, std::uint32_t size) {
  std::uint64_t left = size;
  while (left > 0) {
    std::uint32_t length = 0;
    if (left < 4 || !in.value(length) || length > left - 4 || !in.skip(length)) {
      return false;
    }
    left -= 4 + std::uint64_t(length);
  }
  return true;
}

/// One attribute's value, `size` bytes; false when it does not parse as its type says.
bool read_attribute(HeaderBytes& in, const std::string& name, const std::string& type,
                    std::uint32_t size, ExrLayout& layout) {
  const size_t end = in.position() + size;
  const std::uint32_t fixed = fixed_attribute_size(type);
  if ((fixed != 0 && size != fixed) || type == "idmanifest" ||
      (type == "floatvector" && size % 4 != 0)) {
    return false;  // idmanifest: compressed sizes inside that OpenEXR trusts; gfield writes none
  }
  if (type == "stringvector") {
    return read_string_vector(in, size);
  }
  if (name == "dataWindow" && type == "box2i" && size == 16) {
    std::int32_t w[4];
    in.value(w);
    layout.min_x = w[0];
    layout.min_y = w[1];
    layout.max_x = w[2];
    layout.max_y = w[3];
  } else if (name == "compression" && type == "compression" && size == 1) {
    std::uint8_t c = 0;
    in.value(c);
    layout.compression = c;
  } else if (name == "tiles" && type == "tiledesc" && size == 9) {
    std::uint8_t mode = 0;
    in.value(layout.tile_x);
    in.value(layout.tile_y);
    in.value(mode);
    layout.tile_mode = mode;
  } else if (type == "chlist") {
    // Any chlist, whatever its name: OpenEXR reads channels up to the empty name, not by size.
    ExrLayout other;
    return read_channels(in, end, name == "channels" ? layout : other);
  } else if (type == "preview") {
    std::uint32_t w = 0, h = 0;
    return in.value(w) && in.value(h) && 8 + 4 * std::uint64_t(w) * h == size && in.skip(size - 8);
  } else {
    return in.skip(size);
  }
  return in.position() == end;
}

/// Reads the header's attributes from `bytes` (the start of a file of `file_size` bytes).
bool read_layout(const std::string& bytes, std::uint64_t file_size, ExrLayout& layout,
                 std::string& what) {
  HeaderBytes in(bytes);
  std::uint32_t magic = 0, version = 0;
  if (!in.value(magic) || magic != 20000630 || !in.value(version)) {
    what = "not an OpenEXR file (bad magic number)";
    return false;
  }
  if ((version & 0xFF) != 2 || (version & (kDeepFlag | kMultipartFlag)) != 0) {
    what = "unsupported OpenEXR file (only single-part, non-deep version 2 files are read)";
    return false;
  }
  layout.tiled = (version & kTiledFlag) != 0;
  std::string name, type;
  while (true) {
    if (!in.string(name)) {
      what = "truncated or corrupt header (an attribute name)";
      return false;
    }
    if (name.empty()) {
      return true;
    }
    std::uint32_t size = 0;
    if (!in.string(type) || !in.value(size) || size > file_size - in.position() ||
        in.position() + std::uint64_t(size) > bytes.size()) {
      what = "truncated or corrupt header (attribute '" + printable(name) +
             "' does not fit in the file)";
      return false;
    }
    if (!read_attribute(in, name, type, size, layout)) {
      what = "corrupt header attribute '" + printable(name) + "' of type '" + printable(type) + "'";
      return false;
    }
  }
}

/// Scanlines per chunk of each compression (OpenEXR: NO, RLE, ZIPS, ZIP, PIZ, PXR24, B44, B44A,
/// DWAA, DWAB); 0 for unknown ones.
int lines_per_chunk(int compression) {
  static const int kLines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
  return compression >= 0 && compression < 10 ? kLines[compression] : 0;
}

/// The checks of the layout against the file size and the limits.
bool check_layout(const ExrLayout& l, std::uint64_t file_size, int max_width, int max_height,
                  std::initializer_list<const char*> wanted, std::string& what) {
  const std::int64_t width = l.max_x - l.min_x + 1, height = l.max_y - l.min_y + 1;
  constexpr std::int64_t kMaxOrigin = std::int64_t(1) << 30;
  if (width < 1 || height < 1 || width > max_width || height > max_height ||
      std::max(std::abs(l.min_x), std::abs(l.min_y)) > kMaxOrigin) {
    what = "data window " + std::to_string(width) + "x" + std::to_string(height) + " at (" +
           std::to_string(l.min_x) + ", " + std::to_string(l.min_y) + ") is empty or larger than " +
           std::to_string(max_width) + "x" + std::to_string(max_height);
    return false;
  }
  const int lines = lines_per_chunk(l.compression);
  if (lines == 0) {
    what = "unknown compression " + std::to_string(l.compression);
    return false;
  }
  std::uint64_t chunks = std::uint64_t((height + lines - 1) / lines);
  if (l.tiled) {
    if (l.tile_mode != 0 || l.tile_x < 1 || l.tile_y < 1) {
      what = "tiled file with mip-map levels or no tile size (single-level tiles only)";
      return false;
    }
    chunks = ((std::uint64_t(width) + l.tile_x - 1) / l.tile_x) *
             ((std::uint64_t(height) + l.tile_y - 1) / l.tile_y);
  }
  std::uint64_t pixel_bytes = 0;
  for (const auto& channel : l.channels) {
    const std::string& name = channel.first;  // (clang 14 lambdas cannot capture a binding)
    const ExrLayout::Channel& c = channel.second;
    const bool is_wanted =
        std::any_of(wanted.begin(), wanted.end(), [&](const char* w) { return name == w; });
    if (is_wanted && (c.x_sampling != 1 || c.y_sampling != 1)) {
      what = "channel '" + printable(name) + "' is subsampled";
      return false;
    }
    const std::uint64_t columns = std::uint64_t((width + c.x_sampling - 1) / c.x_sampling);
    const std::uint64_t rows = std::uint64_t((height + c.y_sampling - 1) / c.y_sampling);
    pixel_bytes += columns * rows * (c.type == 1 ? 2 : 4);
  }
  if (chunks * 8 > file_size || pixel_bytes / kMaxCompressionRatio > file_size) {
    what = "header claims " + std::to_string(width) + "x" + std::to_string(height) + " pixels (" +
           std::to_string(pixel_bytes) + " bytes), more than the file's " +
           std::to_string(file_size) + " bytes can hold (truncated or corrupt)";
    return false;
  }
  return true;
}

}  // namespace

std::string exr_exception_text(const std::exception& e) {
  return printable(e.what());
}

bool open_exr_input(const std::string& filename, int max_width, int max_height,
                    std::initializer_list<const char*> channels,
                    std::unique_ptr<Imf::InputFile>& file, std::string& error) {
  std::error_code ec;
  if (const std::string problem = file_problem(filename); !problem.empty()) {
    error = filename + ": " + problem;
    return false;
  }
  const std::uint64_t file_size = std::filesystem::file_size(filename, ec);
  std::ifstream in(filename, std::ios::binary);
  std::string bytes(size_t(std::min(file_size, kMaxHeaderBytes)), '\0');
  if (ec || !in || !in.read(bytes.data(), std::streamsize(bytes.size()))) {
    error = filename + ": cannot read";
    return false;
  }
  ExrLayout layout;
  std::string what;
  if (!read_layout(bytes, file_size, layout, what) ||
      !check_layout(layout, file_size, max_width, max_height, channels, what)) {
    error = filename + ": " + what;
    return false;
  }
  try {
    file = std::make_unique<Imf::InputFile>(filename.c_str());
  } catch (const std::exception& e) {
    error = filename + ": not a readable OpenEXR file (" + exr_exception_text(e) + ")";
    return false;
  }
  return true;
}

}  // namespace gfield
