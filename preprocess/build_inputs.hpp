#pragma once
// The inputs of an asset build and their content hash, the build id (docs/scale-out.md,
// "Up to date by content"): the mesh file's name and bytes, its textures (an OBJ's mtllib files
// and the maps they name), every option that changes an output, and gfield's version. A batch
// rebuilds an asset exactly when this id differs from the one its files carry; file times are
// never consulted for that (the mesh file's time is recorded beside the id only to spare a
// reader that checks an asset against its mesh a second hash: asset_source.hpp).

#include <cstdint>
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
  /// The mesh file's modification time before it was hashed, ns since the epoch (not hashed:
  /// readers compare it, with the size, before hashing the mesh again; asset_source.hpp).
  std::int64_t mesh_modified_ns = 0;
};

/// Hashes the inputs of building `mesh_path` with `options` (an object of every output-changing
/// option), its textures being the files it names beside itself as mesh_side_files lists them
/// (geometry/mesh_formats.hpp: an OBJ's mtllib files and the maps they name, a PLY's "comment
/// TextureFile" files, a glTF file's external buffers and images; none for OFF and STL; files
/// that do not exist too, outside the mesh's folder only when `outside` is kAllowed). False with
/// an error "FILE: problem" when the mesh cannot be read.
bool hash_build_inputs(const std::string& mesh_path, const nlohmann::json& options,
                       OutsidePaths outside, BuildInputs& inputs, std::string& error);

}  // namespace gfield
