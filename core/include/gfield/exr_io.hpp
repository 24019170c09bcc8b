#pragma once
// OpenEXR files of geometry images (version 2: optional albedo channels; version-1 images are
// read without them) and geometry fields (version 3: compact, every line's hits once; the
// layered versions 2 (K layers) and 1 (one) are read, and version 2 written on request)
// (docs/formats.md).
// Loaders validate the header (format tag, version, size, channels) and return false with an
// error "FILE: problem". Savers write a temporary file beside the target and rename it.

#include <string>

#include "gfield/geometry_field.hpp"
#include "gfield/geometry_image.hpp"

namespace gfield {

/// Channel precision on disk. Geometry-image positions are always FLOAT; this applies to the
/// normal and coverage channels of images and to the U, V channels of fields.
enum class ExrPrecision { kHalf, kFloat };

/// Format version of thickness maps, written and accepted.
inline constexpr int kFormatVersion = 1;
/// Format version of geometry images written (optional channels albedo.R, albedo.G, albedo.B);
/// versions 1 (no albedo) and 2 are read.
inline constexpr int kGeometryImageVersion = 2;
/// Format version of geometry fields written (compact: the nearest-hit table in channels hit.U,
/// hit.V, the line table in channel line and the interior hits in hit.U, hit.V below it);
/// versions 1 (channels U, V: one layer) and 2 (layered: hitL.U, hitL.V per layer L) are read.
inline constexpr int kFieldFormatVersion = 3;
/// The layered format, written by save_layered_geometry_field (`gfield field --format 2`).
inline constexpr int kLayeredFieldVersion = 2;

bool save_geometry_image(const std::string& filename, const GeometryImage& image,
                         ExrPrecision precision, std::string& error);
bool load_geometry_image(const std::string& filename, GeometryImage& image, std::string& error);

bool save_geometry_field(const std::string& filename, const GeometryField& field,
                         ExrPrecision precision, std::string& error);
/// Writes `field` in the layered format of version 2 with K = `layers` (1 to kMaxFieldLayers):
/// layer L of each pair holds hit L of its line from the entry (field_uv), or a miss.
bool save_layered_geometry_field(const std::string& filename, const GeometryField& field,
                                 int layers, ExrPrecision precision, std::string& error);
bool load_geometry_field(const std::string& filename, GeometryField& field, std::string& error);

/// Reads only the header of a gfield EXR: format tag ("geometry-image"/"geometry-field"), box,
/// source, build id, samples per side and layers (0 for images; 1 for version-1 fields; the
/// most hits of a line for version 3). For matching a field with its image cheaply.
struct ExrAssetHeader {
  std::string format;
  int version = 0;
  int width = 0;
  int height = 0;
  Box box;
  std::string source;
  std::string build_id;  ///< gfield.buildId (gfield/build_id.hpp); empty when absent
  int samples_per_side = 0;
  int layers = 0;
};
bool load_asset_header(const std::string& filename, ExrAssetHeader& header, std::string& error);

}  // namespace gfield
