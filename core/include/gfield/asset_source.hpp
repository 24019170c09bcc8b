#pragma once
// An asset bound to the mesh it was built from: its report's record of the mesh file (bytes and
// SHA-256, docs/formats.md, "Report") against the mesh a scene or command names.

#include <cstdint>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "gfield/scene.hpp"

namespace gfield {

/// An asset report's record of the mesh file it was built from ("inputs"."mesh").
struct BuiltMesh {
  std::string file;         ///< its name when built
  std::uint64_t bytes = 0;  ///< its size
  std::string sha256;       ///< SHA-256 of its bytes, hex
  /// Its modification time when hashed, ns since the epoch (the report's "mesh_modified_ns",
  /// beside the hashed inputs: a copy of the same bytes builds the same id); 0: not recorded.
  std::int64_t modified_ns = 0;
};

/// The record of the mesh in a build's hashed inputs (an asset report's "inputs"). False where
/// they hold none of that shape.
bool built_mesh_from_inputs(const nlohmann::json& inputs, BuiltMesh& mesh);
/// The record of the mesh in `report` (an asset report's JSON): built_mesh_from_inputs of its
/// "inputs", and its "mesh_modified_ns" where present.
bool built_mesh_from_report(const nlohmann::json& report, BuiltMesh& mesh);

/// The JSON object of an asset report file, read through the checked reader (a regular file of
/// at most 64 MiB). False with "FILE: problem" otherwise.
bool read_report_json(const std::string& report_file, nlohmann::json& report, std::string& error);

/// The modification time of `file`, ns since the epoch; false where it cannot be read.
bool file_modified_ns(const std::string& file, std::int64_t& ns);

/// The report of the asset whose geometry image is `geometry_image` (NAME.gimage.exr ->
/// NAME.report.json); "" when the name does not end in ".gimage.exr".
std::string asset_report_path(const std::string& geometry_image);

/// Whether the asset of report `report_file` was built from the contents of `mesh_file`: equal
/// sizes, then equal SHA-256 hashes (the size alone tells most other meshes apart without
/// reading them; a file of the recorded size and modification time is taken as built without
/// reading it). False with one line naming both files when they differ, or when the report
/// exists but cannot be read or holds no record of its mesh. An absent report is true with
/// `checked` false: nothing to check against.
bool check_asset_source(const std::string& report_file, const std::string& mesh_file, bool& checked,
                        std::string& error);

/// check_asset_source for the asset DIR/NAME (`name`, its report NAME.report.json), the report
/// read again (up to 3 tries) when the asset was republished while it was read
/// (published_build.hpp).
bool check_asset_source_of(const std::string& name, const std::string& mesh_file, bool& checked,
                           std::string& error);

/// check_asset_source_of for every mesh of `scene` with a geometry image (glTF meshes excepted:
/// `gfield assets` keeps theirs in step). `stale`: the index of the
/// first mesh whose asset was built from another mesh, -1 when none (then `error` says which).
bool check_scene_assets(const Scene& scene, int& stale, std::string& error);

}  // namespace gfield
