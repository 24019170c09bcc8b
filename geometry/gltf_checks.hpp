#pragma once
// The checks of a glTF document's JSON that come before tinygltf reads it (gltf_document.hpp):
// the extensions it requires (gltf_extensions.hpp), indices, the node forest, accessors and
// buffer views against the buffers' lengths, external buffers on disk. Each failure is a
// JsonFailure at a JSON pointer. Internal to the glTF code.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "gfield/confined_path.hpp"
#include "gfield/located_json.hpp"

namespace gfield {

/// Checks `document` (the glTF JSON of a file in `folder`). `bin_bytes` is the size of a .glb's
/// BIN chunk (-1 for a .gltf file); buffer and image URIs must be data: URIs or relative paths
/// inside `folder` unless `outside` is kAllowed (confined_path.hpp). False with `failure`.
bool check_gltf_json(const nlohmann::json& document, const std::string& folder,
                     std::int64_t bin_bytes, OutsidePaths outside, JsonFailure& failure);

/// The node hierarchy of `document` (its indices checked) is a forest: no node its own child,
/// one parent at most, no cycle, the scenes' nodes roots. `visits` grows by the node and child
/// visits the check took: at most 3 per node plus 2 per child, whatever the hierarchy's shape.
bool check_node_forest(const nlohmann::json& document, JsonFailure& failure, std::uint64_t& visits);

/// Bytes of one component of glTF component type `type` (5120 ... 5126; 0 for another).
std::uint64_t gltf_component_bytes(std::int64_t type);
/// Components of glTF accessor type `type` (SCALAR 1 ... MAT4 16; 0 for another).
std::uint64_t gltf_type_components(const std::string& type);

/// A URI's path with %XX escapes decoded (as tinygltf decodes it).
std::string decode_uri(const std::string& uri);

}  // namespace gfield
