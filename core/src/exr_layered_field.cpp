// Layered geometry fields, format versions 1 and 2 (docs/formats.md): read for older assets,
// written for `gfield field --format 2`.

#include "exr_layered_field.hpp"

#include <OpenEXR/ImfIntAttribute.h>

#include "exr_common.hpp"
#include "gfield/field_lines.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

using namespace exr;

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

}  // namespace

/// A layered field's table (version 1 or 2) from an open file whose header was checked.
bool exr::read_layered_table(const std::string& filename, Imf::InputFile& file,
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

}  // namespace gfield
