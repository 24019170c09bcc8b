#pragma once
// glTF documents whose meshes are compressed (KHR_draco_mesh_compression primitives,
// EXT_meshopt_compression buffer views) rewritten as plain ones before tinygltf reads them: every
// buffer read (gltf_buffers.hpp), every compressed view and primitive decoded (gltf_meshopt.hpp,
// gltf_draco.hpp) within a budget checked before any decoder runs, and the document given one
// buffer holding all of it, as a .glb's BIN chunk. Indices of buffer views and accessors stay as
// they were (a Draco accessor gets a new buffer view at the end), so a JSON pointer into the
// rewritten document names the same thing in the file. Internal to the glTF code.

#include <cstdint>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/gltf_checks.hpp"

namespace gfield {

/// True when `document` has a Draco primitive, a meshopt buffer view or a meshopt fallback
/// buffer: what tinygltf cannot read.
bool gltf_is_compressed(const nlohmann::json& document);

/// `document` (checked by check_gltf_json) with its compressed data decoded: `json` the rewritten
/// document (one buffer, no compression extensions on views and primitives), `bin` its buffer.
/// The decoded views and accessors, with the buffers, must fit in kMaxMeshFileBytes, checked
/// before decoding. False with `failure` (a pointer into the document).
/// `draco_accessors` receives the accessors decoded from Draco.
bool decompress_gltf(const nlohmann::json& document, const std::string& folder,
                     const std::string& bin_chunk, nlohmann::json& json, std::string& bin,
                     std::set<int>& draco_accessors, JsonFailure& failure);

}  // namespace gfield
