#pragma once
// The bytes of a glTF document's buffers, read by gfield itself where it must decode compressed
// data before tinygltf sees the file (gltf_decompress.hpp). Internal to the glTF code.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/gltf_checks.hpp"

namespace gfield {

/// One buffer's bytes: its byteLength of them, or none for an EXT_meshopt_compression fallback
/// buffer (a buffer without a uri that only compressed buffer views decode into).
struct GltfBufferBytes {
  std::string bytes;
  bool fallback = false;
};

/// True for buffer `buffer` (a JSON object) marked {"extensions": {"EXT_meshopt_compression":
/// {"fallback": true}}}.
bool is_meshopt_fallback(const nlohmann::json& buffer);

/// Reads every buffer of `document` (already checked by check_gltf_json: URIs confined, external
/// files present with their byteLength): a .glb's first buffer from `bin_chunk`, data: URIs
/// decoded (base64, exactly byteLength bytes), external files from `folder`. False with
/// `failure` for data that does not decode or a file that changed since it was checked.
bool read_gltf_buffers(const nlohmann::json& document, const std::string& folder,
                       const std::string& bin_chunk, std::vector<GltfBufferBytes>& buffers,
                       JsonFailure& failure);

}  // namespace gfield
