#include "geometry/gltf_buffers.hpp"

#include <filesystem>

#include "geometry/gltf_document.hpp"
#include "gfield/file_read.hpp"
#include "gfield/limits.hpp"
#include "gfield/located_json.hpp"

namespace gfield {

bool is_meshopt_fallback(const nlohmann::json& buffer) {
  const nlohmann::json* fallback =
      json_at(buffer, {"extensions", "EXT_meshopt_compression", "fallback"});
  return fallback != nullptr && fallback->is_boolean() && fallback->get<bool>();
}

bool read_gltf_buffers(const nlohmann::json& document, const std::string& folder,
                       const std::string& bin_chunk, std::vector<GltfBufferBytes>& buffers,
                       JsonFailure& failure) {
  buffers.clear();
  const nlohmann::json empty = nlohmann::json::array();
  const nlohmann::json& list = document.contains("buffers") ? document["buffers"] : empty;
  for (size_t b = 0; b < list.size(); ++b) {
    const nlohmann::json& buffer = list[b];
    const std::string pointer = json_pointer_child("/buffers", b);
    const size_t length = buffer.value("byteLength", size_t(0));
    const nlohmann::json* uri = json_at(buffer, {"uri"});
    uri = uri != nullptr && uri->is_string() ? uri : nullptr;  // as check_gltf_json reads it
    GltfBufferBytes bytes;
    std::string problem;
    if (uri == nullptr && is_meshopt_fallback(buffer)) {
      bytes.fallback = true;
    } else if (uri == nullptr) {  // a .glb's BIN chunk (check_gltf_json allows no other)
      bytes.bytes = bin_chunk.substr(0, length);
    } else if (uri->get<std::string>().rfind("data:", 0) == 0) {
      std::vector<unsigned char> data;
      std::string mime;
      if (!tinygltf::DecodeDataURI(&data, mime, uri->get<std::string>(), length, true)) {
        failure = {json_pointer_child(pointer, "uri"),
                   "a data: URI that is not base64 data of byteLength " + std::to_string(length) +
                       " bytes"};
        return false;
      }
      bytes.bytes.assign(data.begin(), data.end());
    } else {
      const std::string file =
          (std::filesystem::path(folder) / decode_uri(uri->get<std::string>())).string();
      if (!read_file(file, kMaxMeshFileBytes, bytes.bytes, problem) ||
          bytes.bytes.size() != length) {
        failure = {json_pointer_child(pointer, "uri"),
                   problem.empty() ? file + " changed while it was read" : problem};
        return false;
      }
    }
    buffers.push_back(std::move(bytes));
  }
  return true;
}

}  // namespace gfield
