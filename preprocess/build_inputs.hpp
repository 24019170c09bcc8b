#pragma once
// The inputs of an asset build and their content hash, the build id (docs/scale-out.md,
// "Up to date by content"): the mesh file's name and bytes, its textures (an OBJ's mtllib files
// and the maps they name), every option that changes an output, and gfield's version. A batch
// rebuilds an asset exactly when this id differs from the one its files carry; file times are
// never consulted.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gfield/confined_path.hpp"

namespace gfield {

/// Hex digits of a build id: the first 128 bits of a SHA-256.
inline constexpr size_t kBuildIdDigits = 32;

struct BuildInputs {
  /// What was hashed: {"scheme", "gfield", "mesh": {"file", "bytes", "sha256"},
  /// "textures": [{"file", "sha256" (null: missing)}], "options": {...}}.
  nlohmann::json record;
  std::string build_id;  ///< the first kBuildIdDigits hex digits of SHA-256(record.dump())
};

/// The texture files a mesh names, as paths relative to the working folder: for an OBJ, its
/// mtllib files and the maps (map_Kd, bump, ...) they name; for a glTF file, its external
/// buffers and images; for a PLY, its "comment TextureFile" files; none for OFF and STL. Files that
/// do not exist are listed too (their appearance changes the build); files outside the mesh's
/// folder only when `outside` is kAllowed (the build refuses them otherwise: confined_path.hpp).
std::vector<std::string> mesh_texture_files(const std::string& mesh_path, OutsidePaths outside);

/// Hashes the inputs of building `mesh_path` with `options` (an object of every output-changing
/// option), reading the files it names as mesh_texture_files lists them. False with an error
/// "FILE: problem" when the mesh cannot be read.
bool hash_build_inputs(const std::string& mesh_path, const nlohmann::json& options,
                       OutsidePaths outside, BuildInputs& inputs, std::string& error);

}  // namespace gfield
