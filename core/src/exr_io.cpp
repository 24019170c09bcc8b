#include "gfield/exr_io.hpp"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <glm/gtx/compatibility.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

#include "exr_input.hpp"
#include "gfield/atomic_file.hpp"
#include "gfield/build_id.hpp"
#include "gfield/limits.hpp"
#include "gfield/printable.hpp"

namespace gfield {

namespace {

constexpr const char* kImageTag = "geometry-image";
constexpr const char* kFieldTag = "geometry-field";
constexpr int kMinSamplesPerSide = 1;
constexpr int kMaxSamplesPerSide = 64;
constexpr int kMaxFieldSide = 6 * kMaxSamplesPerSide * kMaxSamplesPerSide;

void use_all_cores() {
  static std::once_flag once;
  // An application that sized OpenEXR's pool itself (gfield --threads) keeps its size.
  std::call_once(once, [] {
    if (Imf::globalThreadCount() == 0) {
      Imf::setGlobalThreadCount(int(std::thread::hardware_concurrency()));
    }
  });
}

Imf::PixelType pixel_type(ExrPrecision precision) {
  return precision == ExrPrecision::kHalf ? Imf::HALF : Imf::FLOAT;
}

Imath::V3f to_imath(glm::vec3 v) {
  return {v.x, v.y, v.z};
}
glm::vec3 to_glm(const Imath::V3f& v) {
  return {v.x, v.y, v.z};
}

Imf::Header make_header(int width, int height, const char* tag, int version, const Box& box,
                        const std::string& source, const std::string& build_id) {
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.insert("gfield.format", Imf::StringAttribute(tag));
  header.insert("gfield.version", Imf::IntAttribute(version));
  header.insert("gfield.boxMin", Imf::V3fAttribute(to_imath(box.min)));
  header.insert("gfield.boxMax", Imf::V3fAttribute(to_imath(box.max)));
  header.insert("gfield.source", Imf::StringAttribute(source));
  if (!build_id.empty()) {
    header.insert(kBuildIdAttribute, Imf::StringAttribute(build_id));
  }
  return header;
}

// A float slice over an interleaved array of `components` floats per pixel.
Imf::Slice float_slice(const float* base, int components, int width) {
  const size_t x_stride = sizeof(float) * size_t(components);
  return Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(base)), x_stride,
                    x_stride * size_t(width));
}

// Frame buffer for writing: OpenEXR converts pixel types when reading but not when writing, so
// HALF channels get a converted copy (kept alive in `halves` until the write is done).
struct OutputChannels {
  Imf::FrameBuffer frame_buffer;
  std::vector<std::vector<half>> halves;

  void add(Imf::Header& header, const char* name, Imf::PixelType type, const float* base,
           int components, size_t count, int width) {
    header.channels().insert(name, Imf::Channel(type));
    if (type == Imf::FLOAT) {
      frame_buffer.insert(name, float_slice(base, components, width));
      return;
    }
    std::vector<half>& h = halves.emplace_back(count);
    for (size_t i = 0; i < count; ++i) {
      h[i] = half(base[i * size_t(components)]);
    }
    frame_buffer.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(h.data()), sizeof(half),
                                         sizeof(half) * size_t(width)));
  }
};

bool write_exr(const std::string& filename, const Imf::Header& header,
               const Imf::FrameBuffer& frame_buffer, int height, std::string& error) {
  use_all_cores();
  TemporaryFile tmp(filename);
  try {
    Imf::OutputFile file(tmp.path().c_str(), header);
    file.setFrameBuffer(frame_buffer);
    file.writePixels(height);
  } catch (const std::exception& e) {
    error = filename + ": cannot write OpenEXR file (" + tmp.as_target(e.what()) + ")";
    return false;
  }
  return tmp.commit(error);
}

/// "(x, y, z)" for messages.
std::string vec_text(glm::vec3 v) {
  char text[96];
  std::snprintf(text, sizeof(text), "(%g, %g, %g)", v.x, v.y, v.z);
  return text;
}

// Reads and checks the gfield header attributes.
bool read_header(const std::string& filename, const Imf::Header& h, ExrAssetHeader& out,
                 std::string& error) {
  const auto* format = h.findTypedAttribute<Imf::StringAttribute>("gfield.format");
  if (!format) {
    error = filename + ": not a gfield asset (no gfield.format attribute)";
    return false;
  }
  out.format = format->value();
  const auto* version = h.findTypedAttribute<Imf::IntAttribute>("gfield.version");
  if (!version) {
    error = filename + ": missing gfield.version attribute";
    return false;
  }
  out.version = version->value();
  const auto* box_min = h.findTypedAttribute<Imf::V3fAttribute>("gfield.boxMin");
  const auto* box_max = h.findTypedAttribute<Imf::V3fAttribute>("gfield.boxMax");
  if (!box_min || !box_max) {
    error = filename + ": missing gfield.boxMin/gfield.boxMax attribute";
    return false;
  }
  out.box = {to_glm(box_min->value()), to_glm(box_max->value())};
  const float limit = float(kMaxAssetCoordinate);
  if (!glm::all(glm::isfinite(out.box.min)) || !glm::all(glm::isfinite(out.box.max)) ||
      !glm::all(glm::lessThan(out.box.min, out.box.max)) ||
      glm::any(glm::greaterThan(glm::abs(out.box.min), glm::vec3(limit))) ||
      glm::any(glm::greaterThan(glm::abs(out.box.max), glm::vec3(limit)))) {
    error = filename + ": invalid box " + vec_text(out.box.min) + " - " + vec_text(out.box.max) +
            " (gfield.boxMin must be below gfield.boxMax, both finite and within +-1e16)";
    return false;
  }
  const auto* source = h.findTypedAttribute<Imf::StringAttribute>("gfield.source");
  out.source = source ? source->value() : std::string();
  const auto* build_id = h.findTypedAttribute<Imf::StringAttribute>(kBuildIdAttribute);
  out.build_id = build_id ? build_id->value() : std::string();
  const auto* samples = h.findTypedAttribute<Imf::IntAttribute>("gfield.samplesPerSide");
  out.samples_per_side = samples ? samples->value() : 0;
  const auto* layers = h.findTypedAttribute<Imf::IntAttribute>("gfield.layers");
  out.layers = layers ? layers->value() : (out.format == kFieldTag && out.version == 1 ? 1 : 0);
  const Imath::Box2i dw = h.dataWindow();
  out.width = dw.max.x - dw.min.x + 1;
  out.height = dw.max.y - dw.min.y + 1;
  return true;
}

/// A ray offset a geometry image may carry (NaN: no).
bool valid_ray_offset(float ray_offset) {
  return ray_offset >= kMinRayOffset && ray_offset <= kMaxRayOffset;
}

/// The optional gfield.rayOffset of a geometry image (kMinRayOffset when absent).
bool read_ray_offset(const std::string& filename, const Imf::Header& h, float& ray_offset,
                     std::string& error) {
  const auto* attribute = h.findTypedAttribute<Imf::FloatAttribute>("gfield.rayOffset");
  ray_offset = attribute ? attribute->value() : kMinRayOffset;
  if (!valid_ray_offset(ray_offset)) {
    char text[160];
    std::snprintf(text, sizeof(text), ": gfield.rayOffset %g outside [%g, %g] (box diagonals)",
                  double(ray_offset), double(kMinRayOffset), double(kMaxRayOffset));
    error = filename + text;
    return false;
  }
  return true;
}

/// Positions finite and within kMaxAssetCoordinate, normal components within
/// kMaxNormalComponent, coverage in [0, 1], albedo components in [0, kMaxColorComponent].
bool check_texels(const std::string& filename, const GeometryImage& image, std::string& error) {
  const glm::vec3 limit(static_cast<float>(kMaxAssetCoordinate));
  const glm::vec3 normal_limit(static_cast<float>(kMaxNormalComponent));
  const glm::vec3 color_limit(static_cast<float>(kMaxColorComponent));
  for (size_t t = 0; t < image.position.size(); ++t) {
    const float a = image.coverage[t];
    const bool albedo_ok = image.albedo.empty() ||
                           (glm::all(glm::greaterThanEqual(image.albedo[t], glm::vec3(0.0f))) &&
                            glm::all(glm::lessThanEqual(image.albedo[t], color_limit)));
    if (!glm::all(glm::lessThanEqual(glm::abs(image.position[t]), limit)) ||
        !glm::all(glm::lessThanEqual(glm::abs(image.normal[t]), normal_limit)) ||
        !(a >= 0.0f && a <= 1.0f) || !albedo_ok) {
      error = filename + ": texel (" + std::to_string(t % size_t(image.size)) + ", " +
              std::to_string(t / size_t(image.size)) + "): position " +
              vec_text(image.position[t]) + ", normal " + vec_text(image.normal[t]) +
              ", coverage " + std::to_string(a) +
              (image.albedo.empty() ? std::string() : " or albedo " + vec_text(image.albedo[t])) +
              " out of range (positions within +-1e16, normal components within +-2, coverage "
              "in [0,1], albedo in [0,1e6])";
      return false;
    }
  }
  return true;
}

/// The format tag is `tag` and the version within [oldest_version, newest_version].
bool check_format(const std::string& filename, const ExrAssetHeader& header, const char* tag,
                  int oldest_version, int newest_version, std::string& error) {
  if (header.format != tag) {
    error =
        filename + ": wrong format tag '" + printable(header.format) + "' (expected '" + tag + "')";
    return false;
  }
  if (header.version < oldest_version || header.version > newest_version) {
    const std::string versions = oldest_version == newest_version
                                     ? "version " + std::to_string(newest_version)
                                     : "versions " + std::to_string(oldest_version) + " to " +
                                           std::to_string(newest_version);
    error = filename + ": unsupported format version " + std::to_string(header.version) +
            " (this build reads " + versions + ")";
    return false;
  }
  return true;
}

constexpr const char* kAlbedoChannels[3] = {"albedo.R", "albedo.G", "albedo.B"};

/// Whether a geometry image's header holds albedo: all three channels (version 2), or none.
bool albedo_channels(const std::string& filename, const Imf::Header& h, bool& present,
                     std::string& error) {
  int found = 0;
  for (const char* name : kAlbedoChannels) {
    found += h.channels().findChannel(name) != nullptr;
  }
  present = found == 3;
  if (found != 0 && found != 3) {
    error = filename + ": albedo needs all three channels albedo.R, albedo.G, albedo.B";
    return false;
  }
  return true;
}

bool check_channels(const std::string& filename, const Imf::Header& h,
                    std::initializer_list<const char*> names, std::string& error) {
  for (const char* name : names) {
    if (!h.channels().findChannel(name)) {
      error = filename + ": missing channel '" + name + "'";
      return false;
    }
  }
  return true;
}

bool open_input(const std::string& filename, int max_side,
                std::initializer_list<const char*> channels, std::unique_ptr<Imf::InputFile>& file,
                std::string& error) {
  use_all_cores();
  return open_exr_input(filename, max_side, max_side, channels, file, error);
}

bool read_pixels(const std::string& filename, Imf::InputFile& file,
                 const Imf::FrameBuffer& frame_buffer, std::string& error) {
  try {
    const Imath::Box2i dw = file.header().dataWindow();
    file.setFrameBuffer(frame_buffer);
    file.readPixels(dw.min.y, dw.max.y);
  } catch (const std::exception& e) {
    error = filename + ": truncated or corrupt pixel data (" + exr_exception_text(e) + ")";
    return false;
  }
  return true;
}

// Channel of layer `layer` in a version-2 field: hit0.U, hit0.V, hit1.U, ...
std::string field_channel(int layer, char component) {
  return "hit" + std::to_string(layer) + "." + component;
}

// The channels of a field's layers (U, V per layer, in order) after checking that they match
// the header: version 1 holds U and V; version 2 holds hitL.U and hitL.V for the gfield.layers
// layers and no others. Every channel HALF or FLOAT, all alike.
bool check_field_channels(const std::string& filename, const Imf::Header& h,
                          const ExrAssetHeader& header, std::vector<std::string>& names,
                          std::string& error) {
  if (header.layers < 1 || header.layers > kMaxFieldLayers) {
    error = filename + ": gfield.layers " + std::to_string(header.layers) +
            " missing or out of range [1, " + std::to_string(kMaxFieldLayers) + "]";
    return false;
  }
  if (header.version == 1 && header.layers != 1) {
    error = filename + ": a version-1 field holds one layer, but gfield.layers says " +
            std::to_string(header.layers);
    return false;
  }
  names = header.version == 1 ? std::vector<std::string>{"U", "V"} : std::vector<std::string>{};
  for (int layer = 0; header.version > 1 && layer < header.layers; ++layer) {
    names.push_back(field_channel(layer, 'U'));
    names.push_back(field_channel(layer, 'V'));
  }
  int stored_layers = 0;
  for (auto c = h.channels().begin(); c != h.channels().end(); ++c) {
    const std::string name = c.name();
    stored_layers += int(name.rfind("hit", 0) == 0 && name.size() > 2 &&
                         name.compare(name.size() - 2, 2, ".U") == 0);
  }
  if (header.version > 1 && stored_layers != header.layers) {
    error = filename + ": " + std::to_string(stored_layers) +
            " hit layers in the channels, but gfield.layers says " + std::to_string(header.layers);
    return false;
  }
  const Imf::Channel* first = nullptr;
  for (const std::string& name : names) {
    const Imf::Channel* channel = h.channels().findChannel(name);
    if (!channel) {
      error = filename + ": missing channel '" + name +
              "' (gfield.layers = " + std::to_string(header.layers) + ")";
      return false;
    }
    if (channel->type != Imf::HALF && channel->type != Imf::FLOAT) {
      error = filename + ": channel '" + name + "' is not HALF or FLOAT";
      return false;
    }
    if (channel->xSampling != 1 || channel->ySampling != 1) {
      error = filename + ": channel '" + name + "' is subsampled";
      return false;
    }
    first = first ? first : channel;
    if (channel->type != first->type) {
      error = filename + ": channel '" + name + "' is " +
              (channel->type == Imf::HALF ? "HALF" : "FLOAT") + " but '" + names[0] + "' is " +
              (first->type == Imf::HALF ? "HALF" : "FLOAT") + " (one bit depth for all layers)";
      return false;
    }
  }
  return true;
}

// N in range and the data window (6N^2)^2.
bool check_field_size(const std::string& filename, const ExrAssetHeader& header,
                      std::string& error) {
  const int n = header.samples_per_side;
  if (n < kMinSamplesPerSide || n > kMaxSamplesPerSide) {
    error = filename + ": gfield.samplesPerSide " + std::to_string(n) + " missing or out of range";
    return false;
  }
  const int side = sample_count(n);
  if (header.width != side || header.height != side) {
    error = filename + ": geometry field is " + std::to_string(header.width) + "x" +
            std::to_string(header.height) + ", expected " + std::to_string(side) + "x" +
            std::to_string(side) + " for N = " + std::to_string(n);
    return false;
  }
  return true;
}

// Every stored value is a uv in [0,1]^2, a miss or "no ray"; along a line, a miss is followed by
// misses only, and "no ray" holds in every layer or none.
bool check_field_values(const std::string& filename, const GeometryField& field,
                        std::string& error) {
  const size_t side = size_t(field_side(field));
  const size_t count = field_layer_size(field);
  const auto where = [&](size_t k) {
    return " at entry " + std::to_string(k / side) + ", exit " + std::to_string(k % side);
  };
  for (size_t k = 0; k < count; ++k) {
    for (int layer = 0; layer < field.layers; ++layer) {
      const glm::vec2 v = field.uv[size_t(layer) * count + k];
      const bool hit = v.x >= 0.0f && v.x <= 1.0f && v.y >= 0.0f && v.y <= 1.0f;
      const bool miss = v.x == kFieldMiss && v.y == kFieldMiss;
      const bool no_ray = v.x == kFieldNoRay && v.y == kFieldNoRay;
      if (!hit && !miss && !no_ray) {
        error = filename + ": invalid uv (" + std::to_string(v.x) + ", " + std::to_string(v.y) +
                ")" + where(k) + ", layer " + std::to_string(layer);
        return false;
      }
      if (layer == 0) {
        continue;
      }
      const glm::vec2 before = field.uv[size_t(layer - 1) * count + k];
      if (no_ray != (before.x == kFieldNoRay) || (hit && before.x < 0.0f)) {
        error = filename + ": layer " + std::to_string(layer) + " disagrees with layer " +
                std::to_string(layer - 1) + where(k) +
                " (a hit after a miss, or \"no ray\" in some layers only)";
        return false;
      }
    }
  }
  return true;
}

}  // namespace

bool save_geometry_image(const std::string& filename, const GeometryImage& image,
                         ExrPrecision precision, std::string& error) {
  const size_t texels = size_t(image.size) * size_t(image.size);
  if (image.size <= 0 || image.position.size() != texels || image.normal.size() != texels ||
      image.coverage.size() != texels) {
    error =
        filename + ": geometry image arrays do not match its size " + std::to_string(image.size);
    return false;
  }
  if (!image.albedo.empty() && image.albedo.size() != texels) {
    error =
        filename + ": geometry image albedo does not match its size " + std::to_string(image.size);
    return false;
  }
  if (!valid_ray_offset(image.ray_offset)) {
    error = filename + ": ray offset " + std::to_string(image.ray_offset) + " out of range";
    return false;
  }
  Imf::Header header = make_header(image.size, image.size, kImageTag, kGeometryImageVersion,
                                   image.box, image.source, image.build_id);
  header.insert("gfield.rayOffset", Imf::FloatAttribute(image.ray_offset));
  const Imf::PixelType type = pixel_type(precision);
  const float* p = &image.position[0].x;
  const float* n = &image.normal[0].x;
  const int w = image.size;
  OutputChannels out;
  out.add(header, "P.X", Imf::FLOAT, p + 0, 3, texels, w);
  out.add(header, "P.Y", Imf::FLOAT, p + 1, 3, texels, w);
  out.add(header, "P.Z", Imf::FLOAT, p + 2, 3, texels, w);
  out.add(header, "N.X", type, n + 0, 3, texels, w);
  out.add(header, "N.Y", type, n + 1, 3, texels, w);
  out.add(header, "N.Z", type, n + 2, 3, texels, w);
  out.add(header, "A", type, image.coverage.data(), 1, texels, w);
  if (!image.albedo.empty()) {
    const float* a = &image.albedo[0].x;
    for (int c = 0; c < 3; ++c) {
      out.add(header, kAlbedoChannels[c], type, a + c, 3, texels, w);
    }
  }
  return write_exr(filename, header, out.frame_buffer, image.size, error);
}

bool load_geometry_image(const std::string& filename, GeometryImage& image, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  if (!open_input(filename, kMaxGeometryImageSide,
                  {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "A", kAlbedoChannels[0],
                   kAlbedoChannels[1], kAlbedoChannels[2]},
                  file, error)) {
    return false;
  }
  ExrAssetHeader header;
  bool albedo = false;
  GeometryImage out;
  if (!read_header(filename, file->header(), header, error) ||
      !check_format(filename, header, kImageTag, 1, kGeometryImageVersion, error) ||
      !check_channels(filename, file->header(), {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "A"},
                      error) ||
      !albedo_channels(filename, file->header(), albedo, error) ||
      !read_ray_offset(filename, file->header(), out.ray_offset, error)) {
    return false;
  }
  if (albedo && header.version < 2) {
    error = filename + ": albedo channels in a version-1 geometry image";
    return false;
  }
  if (header.width != header.height || header.width < 2) {
    error = filename + ": geometry image must be square and at least 2x2, found " +
            std::to_string(header.width) + "x" + std::to_string(header.height);
    return false;
  }
  out.size = header.width;
  out.box = header.box;
  out.source = header.source;
  out.build_id = header.build_id;
  const size_t texels = size_t(out.size) * size_t(out.size);
  out.position.resize(texels);
  out.normal.resize(texels);
  out.coverage.resize(texels);
  const Imath::Box2i dw = file->header().dataWindow();
  // OpenEXR addresses the frame buffer with absolute data-window coordinates.
  const ptrdiff_t origin = ptrdiff_t(dw.min.y) * out.size + dw.min.x;
  Imf::FrameBuffer fb;
  float* p = &out.position[0].x - origin * 3;
  float* n = &out.normal[0].x - origin * 3;
  fb.insert("P.X", float_slice(p + 0, 3, out.size));
  fb.insert("P.Y", float_slice(p + 1, 3, out.size));
  fb.insert("P.Z", float_slice(p + 2, 3, out.size));
  fb.insert("N.X", float_slice(n + 0, 3, out.size));
  fb.insert("N.Y", float_slice(n + 1, 3, out.size));
  fb.insert("N.Z", float_slice(n + 2, 3, out.size));
  fb.insert("A", float_slice(out.coverage.data() - origin, 1, out.size));
  if (albedo) {
    out.albedo.resize(texels);
    float* a = &out.albedo[0].x - origin * 3;
    for (int c = 0; c < 3; ++c) {
      fb.insert(kAlbedoChannels[c], float_slice(a + c, 3, out.size));
    }
  }
  if (!read_pixels(filename, *file, fb, error)) {
    return false;
  }
  if (!check_texels(filename, out, error)) {
    return false;
  }
  image = std::move(out);
  return true;
}

bool save_geometry_field(const std::string& filename, const GeometryField& field,
                         ExrPrecision precision, std::string& error) {
  const int n = field.samples_per_side;
  if (n < kMinSamplesPerSide || n > kMaxSamplesPerSide) {
    error = filename + ": samples per side " + std::to_string(n) + " out of range";
    return false;
  }
  if (field.layers < 1 || field.layers > kMaxFieldLayers) {
    error = filename + ": " + std::to_string(field.layers) + " layers out of range [1, " +
            std::to_string(kMaxFieldLayers) + "]";
    return false;
  }
  const int side = field_side(field);
  if (field.uv.size() != field_layer_size(field) * size_t(field.layers)) {
    error = filename + ": geometry field table does not match N = " + std::to_string(n) + ", " +
            std::to_string(field.layers) + " layers";
    return false;
  }
  Imf::Header header = make_header(side, side, kFieldTag, kFieldFormatVersion, field.box,
                                   field.source, field.build_id);
  header.insert("gfield.samplesPerSide", Imf::IntAttribute(n));
  header.insert("gfield.layers", Imf::IntAttribute(field.layers));
  // zlib level 1 (docs/geometry-field.md): a 3456^2 half table writes ~30% faster than at the
  // default level 4 for ~7% more bytes; RLE is faster still but ~55% larger.
  header.zipCompressionLevel() = 1;
  OutputChannels out;
  const size_t count = field_layer_size(field);
  for (int layer = 0; layer < field.layers; ++layer) {
    const float* uv = &field.uv[size_t(layer) * count].x;
    out.add(header, field_channel(layer, 'U').c_str(), pixel_type(precision), uv, 2, count, side);
    out.add(header, field_channel(layer, 'V').c_str(), pixel_type(precision), uv + 1, 2, count,
            side);
  }
  return write_exr(filename, header, out.frame_buffer, side, error);
}

bool load_geometry_field(const std::string& filename, GeometryField& field, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  if (!open_input(filename, kMaxFieldSide, {}, file, error)) {  // channels: check_field_channels
    return false;
  }
  ExrAssetHeader header;
  std::vector<std::string> channels;
  if (!read_header(filename, file->header(), header, error) ||
      !check_format(filename, header, kFieldTag, 1, kFieldFormatVersion, error) ||
      !check_field_channels(filename, file->header(), header, channels, error) ||
      !check_field_size(filename, header, error)) {
    return false;
  }
  GeometryField out;
  out.samples_per_side = header.samples_per_side;
  out.layers = header.layers;
  out.box = header.box;
  out.source = header.source;
  out.build_id = header.build_id;
  const int side = sample_count(out.samples_per_side);
  const size_t count = field_layer_size(out);
  out.uv.resize(count * size_t(out.layers));
  const Imath::Box2i dw = file->header().dataWindow();
  const ptrdiff_t origin = ptrdiff_t(dw.min.y) * side + dw.min.x;
  Imf::FrameBuffer fb;
  for (int layer = 0; layer < out.layers; ++layer) {
    float* uv = &out.uv[size_t(layer) * count].x - origin * 2;
    fb.insert(channels[size_t(2 * layer)], float_slice(uv + 0, 2, side));
    fb.insert(channels[size_t(2 * layer + 1)], float_slice(uv + 1, 2, side));
  }
  if (!read_pixels(filename, *file, fb, error) || !check_field_values(filename, out, error)) {
    return false;
  }
  field = std::move(out);
  return true;
}

bool load_asset_header(const std::string& filename, ExrAssetHeader& header, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  if (!open_input(filename, std::max(kMaxFieldSide, kMaxGeometryImageSide), {}, file, error)) {
    return false;
  }
  return read_header(filename, file->header(), header, error);
}

}  // namespace gfield
