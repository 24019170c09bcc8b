#pragma once
// NAME.report.json: what an asset build made and measured (docs/formats.md, "Report"). One plain
// struct written by asset_report_to_json and read back only by asset_report_from_json, so that
// no reader looks a field up by name.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gfield/box.hpp"
#include "gfield/exr_io.hpp"
#include "preprocess/asset_files.hpp"
#include "preprocess/field_file_report.hpp"
#include "preprocess/geometry_image_build.hpp"
#include "preprocess/topology.hpp"
#include "preprocess/verify_report.hpp"

namespace gfield {

/// Seconds of a build's stages.
struct AssetStageSeconds {
  double mesh = 0.0;         ///< reading the mesh
  double image = 0.0;        ///< building the geometry image
  double image_write = 0.0;  ///< writing it and the parameterised mesh
  double field = 0.0;        ///< the field's BVH and casts
  double field_write = 0.0;
  double verify = 0.0;  ///< the accuracy report (0 when skipped)
};

struct AssetReport {
  std::string mesh;         ///< the mesh file's name (printable)
  std::string source_path;  ///< its absolute path when built (printable)
  std::string build_id;     ///< gfield/build_id.hpp
  /// The build's hashed inputs (build_inputs.hpp, BuildInputs::record): kept as the JSON that
  /// was hashed; built_mesh_from_inputs reads its record of the mesh file.
  nlohmann::json inputs = nlohmann::json::object();
  std::string mesh_part;  ///< the glTF mesh built ("": the whole file)
  /// The mesh file's modification time when hashed (BuildInputs::mesh_modified_ns; 0: none).
  std::int64_t mesh_modified_ns = 0;
  std::vector<std::string> warnings;  ///< the mesh reader's (printable)
  TopologyReport topology;            ///< of the mesh as read
  GeometryImageReport geometry_image;
  int image_size = 0;                ///< n of the geometry image
  double image_write_seconds = 0.0;  ///< writing the image and the parameterised mesh
  Box box;                           ///< GeometryImage::box
  FieldFileReport geometry_field;
  ExrPrecision field_precision = ExrPrecision::kHalf;  ///< of the field file's uvs
  std::optional<VerifyReport> accuracy;  ///< none when the build skipped it (verify rays 0)
  AssetFiles files;                      ///< the asset's files (printable); report unused
  size_t image_file_bytes = 0;           ///< NAME.gimage.exr (the field's: geometry_field)
  AssetStageSeconds stage_seconds;
  double seconds = 0.0;  ///< the whole build
};

nlohmann::json asset_report_to_json(const AssetReport& report);
/// The inverse of asset_report_to_json. Throws nlohmann::json::exception where `j` is not of
/// that shape (what is missing or of the wrong type in its message).
AssetReport asset_report_from_json(const nlohmann::json& j);

/// Reads an asset report file. False with an error "FILE: problem" when it is not a regular
/// file (checked before it is opened: a FIFO or a folder neither blocks nor throws), cannot be
/// read, is not JSON, or is not an asset report (what is missing or of the wrong type).
bool read_asset_report(const std::string& file, AssetReport& report, std::string& error);

}  // namespace gfield
