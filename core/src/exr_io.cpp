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
#include "gfield/field_lines.hpp"
#include "gfield/limits.hpp"
#include "gfield/printable.hpp"

namespace gfield {

namespace {

constexpr const char* kImageTag = "geometry-image";
constexpr const char* kFieldTag = "geometry-field";
constexpr int kMinSamplesPerSide = 1;
constexpr int kMaxSamplesPerSide = 64;
constexpr int kMaxFieldSide = 6 * kMaxSamplesPerSide * kMaxSamplesPerSide;
// A compact field's channels and attributes (docs/formats.md).
constexpr const char* kHitU = "hit.U";
constexpr const char* kHitV = "hit.V";
constexpr const char* kLineChannel = "line";
constexpr const char* kLineWordsAttribute = "gfield.lineWords";
constexpr const char* kInteriorHitsAttribute = "gfield.interiorHits";

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
// HALF channels get a converted copy (kept alive in `halves` until the write is done). Slices
// start at scanline `first_row` of the data window.
struct OutputChannels {
  Imf::FrameBuffer frame_buffer;
  std::vector<std::vector<half>> halves;
  int first_row = 0;

  void add(Imf::Header& header, const char* name, Imf::PixelType type, const float* base,
           int components, size_t count, int width) {
    header.channels().insert(name, Imf::Channel(type));
    add_slice(name, type, base, components, count, width);
  }
  /// A slice of a channel the header already has.
  void add_slice(const char* name, Imf::PixelType type, const float* base, int components,
                 size_t count, int width) {
    const ptrdiff_t origin = ptrdiff_t(first_row) * width;
    if (type == Imf::FLOAT) {
      frame_buffer.insert(name, float_slice(base - origin * components, components, width));
      return;
    }
    std::vector<half>& h = halves.emplace_back(count);
    for (size_t i = 0; i < count; ++i) {
      h[i] = half(base[i * size_t(components)]);
    }
    frame_buffer.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(h.data() - origin),
                                         sizeof(half), sizeof(half) * size_t(width)));
  }
};

/// Scanlines written from one frame buffer: `rows` of them, after those of the parts before.
struct RowsFrom {
  const Imf::FrameBuffer* frame_buffer;
  int rows;
};

bool write_exr(const std::string& filename, const Imf::Header& header,
               std::initializer_list<RowsFrom> parts, std::string& error) {
  use_all_cores();
  TemporaryFile tmp(filename);
  try {
    Imf::OutputFile file(tmp.path().c_str(), header);
    for (const RowsFrom& part : parts) {
      if (part.rows > 0) {
        file.setFrameBuffer(*part.frame_buffer);
        file.writePixels(part.rows);
      }
    }
  } catch (const std::exception& e) {
    error = filename + ": cannot write OpenEXR file (" + tmp.as_target(e.what()) + ")";
    return false;
  }
  return tmp.commit(error);
}

bool write_exr(const std::string& filename, const Imf::Header& header,
               const Imf::FrameBuffer& frame_buffer, int height, std::string& error) {
  return write_exr(filename, header, {RowsFrom{&frame_buffer, height}}, error);
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

/// Reads scanlines first..last (data-window coordinates) into `frame_buffer`.
bool read_rows(const std::string& filename, Imf::InputFile& file,
               const Imf::FrameBuffer& frame_buffer, int first, int last, std::string& error) {
  try {
    file.setFrameBuffer(frame_buffer);
    file.readPixels(first, last);
  } catch (const std::exception& e) {
    error = filename + ": truncated or corrupt pixel data (" + exr_exception_text(e) + ")";
    return false;
  }
  return true;
}

bool read_pixels(const std::string& filename, Imf::InputFile& file,
                 const Imf::FrameBuffer& frame_buffer, std::string& error) {
  const Imath::Box2i dw = file.header().dataWindow();
  return read_rows(filename, file, frame_buffer, dw.min.y, dw.max.y, error);
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

// Every stored value of a layered table (`layers` tables of side^2) is a uv in [0,1]^2, a miss
// or "no ray"; along a line, a miss is followed by misses only, and "no ray" holds in every
// layer or none.
bool check_layered_values(const std::string& filename, const std::vector<glm::vec2>& table,
                          int side, int layers, std::string& error) {
  const size_t count = size_t(side) * size_t(side);
  const auto where = [&](size_t k) {
    return " at entry " + std::to_string(k / size_t(side)) + ", exit " +
           std::to_string(k % size_t(side));
  };
  for (size_t k = 0; k < count; ++k) {
    for (int layer = 0; layer < layers; ++layer) {
      const glm::vec2 v = table[size_t(layer) * count + k];
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
      const glm::vec2 before = table[size_t(layer - 1) * count + k];
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

// The channels of a compact field: hit.U and hit.V, both HALF or both FLOAT, and line, UINT.
bool check_compact_channels(const std::string& filename, const Imf::Header& h, std::string& error) {
  const Imf::Channel* u = h.channels().findChannel(kHitU);
  const Imf::Channel* v = h.channels().findChannel(kHitV);
  const Imf::Channel* line = h.channels().findChannel(kLineChannel);
  size_t count = 0;
  for (auto c = h.channels().begin(); c != h.channels().end(); ++c) {
    ++count;
  }
  if (u == nullptr || v == nullptr || line == nullptr || count != 3) {
    error = filename +
            ": a version-3 geometry field holds the channels hit.U, hit.V and line, "
            "and no others";
    return false;
  }
  if (u->type != v->type || (u->type != Imf::HALF && u->type != Imf::FLOAT) ||
      line->type != Imf::UINT) {
    error = filename + ": hit.U and hit.V must be both HALF or both FLOAT, line UINT";
    return false;
  }
  return true;
}

// The size of a compact field: N in range, 5N^2 columns, and 6N^2 rows of nearest hits followed
// by as many rows as its line words and interior hits (attributes) need.
bool check_compact_size(const std::string& filename, const Imf::Header& h,
                        const ExrAssetHeader& header, size_t& words, size_t& hits,
                        std::string& error) {
  const int n = header.samples_per_side;
  const auto* word_count = h.findTypedAttribute<Imf::IntAttribute>(kLineWordsAttribute);
  const auto* hit_count = h.findTypedAttribute<Imf::IntAttribute>(kInteriorHitsAttribute);
  if (n < kMinSamplesPerSide || n > kMaxSamplesPerSide || header.layers < 1 ||
      header.layers > kMaxLineHits || word_count == nullptr || hit_count == nullptr ||
      word_count->value() < 0 || hit_count->value() < 0) {
    error = filename + ": gfield.samplesPerSide, gfield.layers (1 to " +
            std::to_string(kMaxLineHits) + "), " + kLineWordsAttribute + " or " +
            kInteriorHitsAttribute + " missing or out of range";
    return false;
  }
  words = size_t(word_count->value());
  hits = size_t(hit_count->value());
  const size_t width = size_t(5 * n * n);
  const size_t rows = size_t(sample_count(n)) + (std::max(words, hits) + width - 1) / width;
  if (size_t(header.width) != width || size_t(header.height) != rows) {
    error = filename + ": geometry field is " + std::to_string(header.width) + "x" +
            std::to_string(header.height) + ", expected " + std::to_string(width) + "x" +
            std::to_string(rows) + " for N = " + std::to_string(n) + ", " + std::to_string(words) +
            " line words and " + std::to_string(hits) + " interior hits";
    return false;
  }
  return true;
}

/// A layered field's table (version 1 or 2) from an open file whose header was checked.
bool read_layered_table(const std::string& filename, Imf::InputFile& file,
                        const ExrAssetHeader& header, std::vector<glm::vec2>& table,
                        std::string& error) {
  std::vector<std::string> channels;
  if (!check_field_channels(filename, file.header(), header, channels, error) ||
      !check_field_size(filename, header, error)) {
    return false;
  }
  const int side = sample_count(header.samples_per_side);
  const size_t count = size_t(side) * size_t(side);
  table.resize(count * size_t(header.layers));
  const Imath::Box2i dw = file.header().dataWindow();
  const ptrdiff_t origin = ptrdiff_t(dw.min.y) * side + dw.min.x;
  Imf::FrameBuffer fb;
  for (int layer = 0; layer < header.layers; ++layer) {
    float* uv = &table[size_t(layer) * count].x - origin * 2;
    fb.insert(channels[size_t(2 * layer)], float_slice(uv + 0, 2, side));
    fb.insert(channels[size_t(2 * layer + 1)], float_slice(uv + 1, 2, side));
  }
  return read_pixels(filename, file, fb, error) &&
         check_layered_values(filename, table, side, header.layers, error);
}

/// A compact field's tables (version 3) from an open file whose header was checked.
bool read_compact_tables(const std::string& filename, Imf::InputFile& file,
                         const ExrAssetHeader& header, GeometryField& out, std::string& error) {
  size_t words = 0, hits = 0;
  if (!check_compact_channels(filename, file.header(), error) ||
      !check_compact_size(filename, file.header(), header, words, hits, error)) {
    return false;
  }
  const int width = field_columns(out);
  const int rows = field_side(out);
  const int extra_rows = header.height - rows;
  out.nearest.resize(field_nearest_size(out));
  const Imath::Box2i dw = file.header().dataWindow();
  Imf::FrameBuffer nearest;
  float* uv = &out.nearest[0].x - (ptrdiff_t(dw.min.y) * width + dw.min.x) * 2;
  nearest.insert(kHitU, float_slice(uv + 0, 2, width));
  nearest.insert(kHitV, float_slice(uv + 1, 2, width));
  if (!read_rows(filename, file, nearest, dw.min.y, dw.min.y + rows - 1, error)) {
    return false;
  }
  if (extra_rows > 0) {
    const size_t padded = size_t(extra_rows) * size_t(width);
    std::vector<glm::vec2> interior(padded);
    std::vector<uint32_t> lines(padded);
    const ptrdiff_t origin = ptrdiff_t(dw.min.y + rows) * width + dw.min.x;
    Imf::FrameBuffer tables;
    tables.insert(kHitU, float_slice(&interior[0].x - origin * 2, 2, width));
    tables.insert(kHitV, float_slice(&interior[0].x - origin * 2 + 1, 2, width));
    tables.insert(kLineChannel,
                  Imf::Slice(Imf::UINT, reinterpret_cast<char*>(lines.data() - origin),
                             sizeof(uint32_t), sizeof(uint32_t) * size_t(width)));
    if (!read_rows(filename, file, tables, dw.min.y + rows, dw.max.y, error)) {
      return false;
    }
    out.interior.assign(interior.begin(), interior.begin() + ptrdiff_t(hits));
    out.lines.assign(lines.begin(), lines.begin() + ptrdiff_t(words));
  }
  std::string why;
  if (!check_field_tables(out, why)) {
    error = filename + ": " + why;
    return false;
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
  header.zipCompressionLevel() = 1;
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
  if (n < kMinSamplesPerSide || n > kMaxSamplesPerSide || field.layers < 1 ||
      field.layers > kMaxLineHits || field.nearest.size() != field_nearest_size(field)) {
    error = filename + ": geometry field tables do not match N = " + std::to_string(n) +
            " or layers " + std::to_string(field.layers) + " out of range";
    return false;
  }
  const int width = field_columns(field);
  const int rows = field_side(field);
  const size_t extra = std::max(field.lines.size(), field.interior.size());
  const int extra_rows = int((extra + size_t(width) - 1) / size_t(width));
  Imf::Header header = make_header(width, rows + extra_rows, kFieldTag, kFieldFormatVersion,
                                   field.box, field.source, field.build_id);
  header.insert("gfield.samplesPerSide", Imf::IntAttribute(n));
  header.insert("gfield.layers", Imf::IntAttribute(field.layers));
  header.insert(kLineWordsAttribute, Imf::IntAttribute(int(field.lines.size())));
  header.insert(kInteriorHitsAttribute, Imf::IntAttribute(int(field.interior.size())));
  header.zipCompressionLevel() = 1;  // docs/geometry-field.md: fast, a few % larger
  // Rows 0..6N^2-1: the nearest hits (line: 0); then the interior hits and the line words.
  OutputChannels nearest;
  const float* uv = &field.nearest[0].x;
  nearest.add(header, kHitU, pixel_type(precision), uv, 2, field.nearest.size(), width);
  nearest.add(header, kHitV, pixel_type(precision), uv + 1, 2, field.nearest.size(), width);
  header.channels().insert(kLineChannel, Imf::Channel(Imf::UINT));
  const std::vector<uint32_t> zero_row(size_t(width), 0u);
  nearest.frame_buffer.insert(
      kLineChannel,
      Imf::Slice(Imf::UINT, reinterpret_cast<char*>(const_cast<uint32_t*>(zero_row.data())),
                 sizeof(uint32_t), 0));
  const size_t padded = size_t(extra_rows) * size_t(width);
  std::vector<glm::vec2> interior(padded, glm::vec2(0.0f));
  std::copy(field.interior.begin(), field.interior.end(), interior.begin());
  std::vector<uint32_t> lines(padded, 0u);
  std::copy(field.lines.begin(), field.lines.end(), lines.begin());
  OutputChannels tables;
  tables.first_row = rows;
  if (padded > 0) {
    const float* hits = &interior[0].x;
    tables.add_slice(kHitU, pixel_type(precision), hits, 2, padded, width);
    tables.add_slice(kHitV, pixel_type(precision), hits + 1, 2, padded, width);
    const ptrdiff_t origin = ptrdiff_t(rows) * width;
    tables.frame_buffer.insert(kLineChannel,
                               Imf::Slice(Imf::UINT, reinterpret_cast<char*>(lines.data() - origin),
                                          sizeof(uint32_t), sizeof(uint32_t) * size_t(width)));
  }
  return write_exr(
      filename, header,
      {RowsFrom{&nearest.frame_buffer, rows}, RowsFrom{&tables.frame_buffer, extra_rows}}, error);
}

bool save_layered_geometry_field(const std::string& filename, const GeometryField& field,
                                 int layers, ExrPrecision precision, std::string& error) {
  const int n = field.samples_per_side;
  if (n < kMinSamplesPerSide || n > kMaxSamplesPerSide || layers < 1 || layers > kMaxFieldLayers ||
      field.nearest.size() != field_nearest_size(field)) {
    error = filename + ": samples per side " + std::to_string(n) + " or layers " +
            std::to_string(layers) + " out of range [1, " + std::to_string(kMaxFieldLayers) + "]";
    return false;
  }
  const int side = field_side(field);
  const size_t count = size_t(side) * size_t(side);
  std::vector<glm::vec2> table(count * size_t(layers));
  glm::vec2 uv[kMaxFieldLayers];
  for (int entry = 0; entry < side; ++entry) {
    for (int exit = 0; exit < side; ++exit) {
      layered_pair(field, entry, exit, layers, uv);
      for (int layer = 0; layer < layers; ++layer) {
        table[size_t(layer) * count + size_t(entry) * size_t(side) + size_t(exit)] = uv[layer];
      }
    }
  }
  Imf::Header header = make_header(side, side, kFieldTag, kLayeredFieldVersion, field.box,
                                   field.source, field.build_id);
  header.insert("gfield.samplesPerSide", Imf::IntAttribute(n));
  header.insert("gfield.layers", Imf::IntAttribute(layers));
  header.zipCompressionLevel() = 1;
  OutputChannels out;
  for (int layer = 0; layer < layers; ++layer) {
    const float* uv = &table[size_t(layer) * count].x;
    out.add(header, field_channel(layer, 'U').c_str(), pixel_type(precision), uv, 2, count, side);
    out.add(header, field_channel(layer, 'V').c_str(), pixel_type(precision), uv + 1, 2, count,
            side);
  }
  return write_exr(filename, header, out.frame_buffer, side, error);
}

bool load_geometry_field(const std::string& filename, GeometryField& field, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  use_all_cores();
  // The rows of a compact field's line table below its 6N^2 rows: at most as many again.
  if (!open_exr_input(filename, kMaxFieldSide, 2 * kMaxFieldSide, {}, file, error)) {
    return false;  // channels: check_field_channels, check_compact_channels
  }
  ExrAssetHeader header;
  if (!read_header(filename, file->header(), header, error) ||
      !check_format(filename, header, kFieldTag, 1, kFieldFormatVersion, error)) {
    return false;
  }
  GeometryField out;
  out.samples_per_side = header.samples_per_side;
  out.layers = header.layers;
  out.box = header.box;
  out.source = header.source;
  out.build_id = header.build_id;
  if (header.version == kFieldFormatVersion) {
    if (!read_compact_tables(filename, *file, header, out, error)) {
      return false;
    }
  } else {
    std::vector<glm::vec2> table;
    if (!read_layered_table(filename, *file, header, table, error)) {
      return false;
    }
    compact_layered_table(table, header.layers, out);
  }
  field = std::move(out);
  return true;
}

bool load_asset_header(const std::string& filename, ExrAssetHeader& header, std::string& error) {
  std::unique_ptr<Imf::InputFile> file;
  use_all_cores();
  const int side = std::max(kMaxFieldSide, kMaxGeometryImageSide);
  if (!open_exr_input(filename, side, 2 * side, {}, file, error)) {
    return false;
  }
  return read_header(filename, file->header(), header, error);
}

}  // namespace gfield
