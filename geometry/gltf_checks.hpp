#pragma once
// The checks of a glTF document's JSON that come before tinygltf reads it (gltf_document.hpp):
// indices, the node forest, accessors and buffer views against the buffers' lengths, external
// buffers on disk. Each failure is a CheckFailure at a JSON pointer. Internal to the glTF code.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace gfield {

/// What is wrong, and where (a JSON pointer into the document).
struct CheckFailure {
  std::string pointer;
  std::string what;
};

/// Checks `document` (the glTF JSON of a file in `folder`). `bin_bytes` is the size of a .glb's
/// BIN chunk (-1 for a .gltf file). False with `failure`.
bool check_gltf_json(const nlohmann::json& document, const std::string& folder,
                     std::int64_t bin_bytes, CheckFailure& failure);

/// A URI's path with %XX escapes decoded (as tinygltf decodes it).
std::string decode_uri(const std::string& uri);

}  // namespace gfield
