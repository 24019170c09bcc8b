#pragma once
// What writing one field file took (the "geometry_field" of an asset report): its layout, GPU
// bytes and times, as a struct, as JSON and as one line of text.

#include <array>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "gfield/exr_io.hpp"
#include "preprocess/field_build.hpp"

namespace gfield {

/// What writing one field file took.
struct FieldFileReport {
  int samples_per_side = 0;
  int image_size = 0;                ///< n of the geometry image (for the GPU bytes)
  int format = kFieldFormatVersion;  ///< 3 (compact) or 2 (layered)
  /// K: the most hits a line holds (format 3), the layers written (format 2)
  int layers = 0;
  size_t memory_estimate = 0;  ///< bytes (field_memory_estimate)
  FieldBuildStats build;       ///< the casts (seconds exclude the BVH and the write)
  size_t table_lines = 0;      ///< lines in the line table (1 hit, or 3 and more)
  size_t line_words = 0;       ///< words of the line table
  size_t interior_hits = 0;
  std::array<size_t, 3> gpu_bytes{};  ///< the field on the GPU at 8, 16 and 32 bits
  double bvh_seconds = 0.0;
  double write_seconds = 0.0;
  size_t file_bytes = 0;
};

nlohmann::json field_file_report_to_json(const FieldFileReport& report);
/// The inverse of field_file_report_to_json but for image_size, which the JSON does not hold
/// (the asset report's geometry image has it). Throws nlohmann::json::exception where `j` is not
/// of that shape.
FieldFileReport field_file_report_from_json(const nlohmann::json& j);

/// "format 3: at most 8 hits per line (99.98% of the lines hold all theirs), GPU 21.3 MB at 8
/// bits, 41.1 MB at 16 bits (image 10.5 MB)": the layout and GPU bytes of a field, one line.
std::string field_layers_summary(const FieldFileReport& report);

}  // namespace gfield
