#pragma once
// Whole assets: mesh file -> NAME.gimage.exr + NAME.gimage.obj + NAME.gfield.exr +
// NAME.report.json (the `gfield field`, `gfield build` and `gfield batch` commands).

#include <string>

#include <nlohmann/json.hpp>

#include "gfield/exr_io.hpp"
#include "preprocess/field_build.hpp"
#include "preprocess/geometry_image_build.hpp"

namespace gfield {

/// What writing one field file took.
struct FieldFileReport {
  int samples_per_side = 0;
  int image_size = 0;          ///< n of the geometry image (for the GPU bytes)
  size_t memory_estimate = 0;  ///< bytes (field_memory_estimate)
  FieldBuildStats build;       ///< the casts (seconds exclude the BVH and the write)
  double bvh_seconds = 0.0;
  double write_seconds = 0.0;
  size_t file_bytes = 0;
};

nlohmann::json field_file_report_to_json(const FieldFileReport& report);

/// Casts the field of `pm` (the parameterised mesh of `image`) with N samples per side and
/// `layers` layers (kAutoLayers: chosen) in the image's box and writes it to `output`
/// (atomically). The field's source is the image's. False with an error "FILE: problem" (N or K
/// out of range or too large for memory included).
bool write_field_file(const GeometryImage& image, const ParameterizedMesh& pm, int samples_per_side,
                      int layers, ExrPrecision precision, const std::string& output,
                      FieldFileReport& report, std::string& error);

/// "K = 2 (chosen: 99.95% of the lines hold all their hits), GPU 47.8 MB at 8 bits": the
/// layers and GPU bytes of a field report, one line.
std::string field_layers_summary(const FieldFileReport& report);

struct AssetOptions {
  GeometryImageOptions image;  ///< size 512 by default
  int samples_per_side = 24;
  int field_layers = kAutoLayers;
  ExrPrecision field_precision = ExrPrecision::kHalf;
  size_t verify_rays = 100000;  ///< rays per family of the report's accuracy (0: skip)
};

/// The four output files of asset `name` (a path without extension: DIR/NAME).
std::string asset_image_path(const std::string& name);
std::string asset_field_path(const std::string& name);
std::string asset_report_path(const std::string& name);

/// True when all outputs of `name` exist and are newer than `mesh_path`.
bool asset_up_to_date(const std::string& mesh_path, const std::string& name);

/// Builds asset `name` from `mesh_path`: topology, geometry image, field, accuracy; writes the
/// files (each atomically, the report last) and returns the report. False with an error
/// "FILE: problem"; files written before a failure stay, the report is not written.
bool build_asset(const std::string& mesh_path, const std::string& name, const AssetOptions& options,
                 nlohmann::json& report, std::string& error);

}  // namespace gfield
