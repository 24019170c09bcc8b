#pragma once
// The document and binary chunk of a .glb as `gfield export-gltf` builds them
// (gltf_writer.cpp, gltf_export_objects.cpp). Internal to the glTF writer.

#include <cstring>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "geometry/glb_container.hpp"

namespace gfield {

/// glTF's codes: component types, buffer view targets.
inline constexpr int kFloat = 5126, kUnsignedInt = 5125;
inline constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

/// The document and its binary chunk as they grow.
class GlbBuilder {
 public:
  nlohmann::json doc = {{"asset", {{"version", "2.0"}, {"generator", "gfield export-gltf"}}},
                        {"scene", 0}};
  std::string bin;

  /// A buffer view of `bytes` (4-byte aligned in the BIN chunk); its index.
  int add_view(const void* bytes, size_t size, int target) {
    while (bin.size() % 4 != 0)
      bin += '\0';
    nlohmann::json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
    if (target != 0)
      view["target"] = target;
    bin.append(static_cast<const char*>(bytes), size);
    return push("bufferViews", view);
  }
  /// An accessor of `count` floats of `type` (VEC2, VEC3, VEC4) or unsigned ints (SCALAR).
  template <class T>
  int add_accessor(const std::vector<T>& data, const char* type, int target) {
    nlohmann::json accessor = {
        {"bufferView", add_view(data.data(), data.size() * sizeof(T), target)},
        {"componentType", std::strcmp(type, "SCALAR") == 0 ? kUnsignedInt : kFloat},
        {"count", data.size()},
        {"type", type}};
    return push("accessors", accessor);
  }
  /// A PNG image and a texture of it; the texture's index.
  int add_png_texture(const std::string& png) {
    const int view = add_view(png.data(), png.size(), 0);
    const int image = push("images", {{"bufferView", view}, {"mimeType", "image/png"}});
    return push("textures", {{"source", image}});
  }
  int push(const char* array, nlohmann::json value) {
    doc[array].push_back(std::move(value));
    return int(doc[array].size()) - 1;
  }
  /// The .glb bytes: header, JSON chunk, BIN chunk (glb_container.hpp).
  std::string glb() {
    if (!bin.empty())
      doc["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}}});
    return glb_bytes(doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), bin);
  }
};

/// A JSON array [x, y, z].
inline nlohmann::json vec(glm::vec3 v) {
  return {v.x, v.y, v.z};
}

}  // namespace gfield
