#include "geometry/gltf_decompress.hpp"

#include <map>

#include "geometry/gltf_buffers.hpp"
#include "geometry/gltf_document.hpp"
#include "geometry/gltf_draco.hpp"
#include "geometry/gltf_meshopt.hpp"
#include "gfield/limits.hpp"
#include "gfield/located_json.hpp"

namespace gfield {
namespace {

using nlohmann::json;

const json kEmptyArray = json::array();

const json& array_of(const json& document, const char* key) {
  return document.contains(key) && document[key].is_array() ? document[key] : kEmptyArray;
}

/// Calls visit(mesh, primitive, extension) for every Draco primitive until one returns false;
/// false when one did.
template <class Visit>
bool for_each_draco_primitive(const json& document, Visit visit) {
  const json& meshes = array_of(document, "meshes");
  for (size_t m = 0; m < meshes.size(); ++m) {
    const json* primitives = json_at(meshes[m], {"primitives"});
    for (size_t p = 0; primitives != nullptr && primitives->is_array() && p < primitives->size();
         ++p) {
      const json* ext = json_at((*primitives)[p], {"extensions", "KHR_draco_mesh_compression"});
      if (ext != nullptr && !visit(m, p, *ext))
        return false;
    }
  }
  return true;
}

/// "/meshes/M/primitives/P/extensions/KHR_draco_mesh_compression".
std::string draco_pointer(size_t m, size_t p) {
  std::string pointer = json_pointer_child(json_pointer_child("/meshes", m), "primitives");
  pointer = json_pointer_child(json_pointer_child(pointer, p), "extensions");
  return json_pointer_child(pointer, "KHR_draco_mesh_compression");
}

/// Bytes of one element of accessor `a` (its componentType and type were checked).
std::uint64_t element_bytes(const json& a) {
  return gltf_component_bytes(a["componentType"].get<std::int64_t>()) *
         gltf_type_components(a["type"].get<std::string>());
}

/// The bytes everything decodes to: buffers, meshopt views, Draco accessors; false with
/// `failure` when they exceed kMaxMeshFileBytes (checked before any decoder runs).
bool check_budget(const json& document, JsonFailure& failure) {
  std::uint64_t total = 0;
  for (const json& buffer : array_of(document, "buffers"))
    total += is_meshopt_fallback(buffer) ? 0 : buffer.value("byteLength", std::uint64_t(0));
  for (const json& view : array_of(document, "bufferViews"))
    if (json_at(view, {"extensions", "EXT_meshopt_compression"}) != nullptr)
      total += view.value("byteLength", std::uint64_t(0));
  const bool ok = for_each_draco_primitive(document, [&](size_t m, size_t p, const json&) {
    const json& primitive = document["meshes"][m]["primitives"][p];
    std::vector<const json*> used;
    if (primitive.contains("indices"))
      used.push_back(&document["accessors"][primitive["indices"].get<size_t>()]);
    const json* attributes = json_at(primitive, {"attributes"});
    if (attributes != nullptr && attributes->is_object())
      for (auto it = attributes->begin(); it != attributes->end(); ++it)
        used.push_back(&document["accessors"][it.value().get<size_t>()]);
    for (const json* a : used)
      total += element_bytes(*a) * (*a)["count"].get<std::uint64_t>();
    failure = {draco_pointer(m, p), "the compressed data would decode to more than " +
                                        std::to_string(kMaxMeshFileBytes) +
                                        " bytes with the file's buffers"};
    return total <= kMaxMeshFileBytes;
  });
  if (ok && total > kMaxMeshFileBytes)
    failure = {"/bufferViews", "the compressed buffer views would decode to more than " +
                                   std::to_string(kMaxMeshFileBytes) + " bytes with the buffers"};
  return ok && total <= kMaxMeshFileBytes;
}

/// Appends `bytes` to `bin` (4-byte aligned); their offset.
std::uint64_t append(std::string& bin, const std::string& bytes) {
  while (bin.size() % 4 != 0)
    bin += '\0';
  const std::uint64_t offset = bin.size();
  bin += bytes;
  return offset;
}

/// Every buffer view into the one buffer of `bin`: plain views moved by their buffer's offset,
/// meshopt views decoded.
bool rewrite_views(const json& document, const std::vector<GltfBufferBytes>& buffers, json& out,
                   std::string& bin, JsonFailure& failure) {
  std::vector<std::uint64_t> offsets;
  for (const GltfBufferBytes& b : buffers)
    offsets.push_back(b.fallback ? 0 : append(bin, b.bytes));
  const json& views = array_of(document, "bufferViews");
  for (size_t v = 0; v < views.size(); ++v) {
    json view = views[v];
    const size_t buffer = view["buffer"].get<size_t>();
    if (json_at(view, {"extensions", "EXT_meshopt_compression"}) != nullptr) {
      std::string decoded;
      if (!decode_meshopt_view(document, v, buffers, decoded, failure))
        return false;
      view["byteOffset"] = append(bin, decoded);
      view["extensions"].erase("EXT_meshopt_compression");
    } else if (buffers[buffer].fallback) {
      failure = {json_pointer_child("/bufferViews", v),
                 "a buffer view of a meshopt fallback buffer without EXT_meshopt_compression"};
      return false;
    } else {
      view["byteOffset"] = view.value("byteOffset", std::uint64_t(0)) + offsets[buffer];
    }
    view["buffer"] = 0;
    out["bufferViews"].push_back(std::move(view));
  }
  return true;
}

/// Every Draco primitive decoded: its accessors given new buffer views at the end of `out`'s.
bool rewrite_draco(const json& document, json& out, std::string& bin, std::set<int>& decoded,
                   JsonFailure& failure) {
  std::map<size_t, std::string> filled;  // accessor -> bytes, for every Draco primitive
  const bool ok = for_each_draco_primitive(document, [&](size_t m, size_t p, const json& ext) {
    const json* view = json_at(ext, {"bufferView"});
    if (view == nullptr || !view->is_number_integer()) {
      failure = {draco_pointer(m, p), "a KHR_draco_mesh_compression without a bufferView"};
      return false;
    }
    const json& plain = out["bufferViews"][view->get<size_t>()];  // an index checked before
    const std::string compressed =
        bin.substr(plain["byteOffset"].get<size_t>(), plain["byteLength"].get<size_t>());
    std::map<size_t, std::string> accessors;
    if (!decode_draco_primitive(document, m, p, compressed, accessors, failure))
      return false;
    for (auto& [index, bytes] : accessors)
      filled[index] = std::move(bytes);
    out["meshes"][m]["primitives"][p]["extensions"].erase("KHR_draco_mesh_compression");
    return true;
  });
  for (auto& [index, bytes] : filled) {
    decoded.insert(int(index));
    json& accessor = out["accessors"][index];
    accessor["byteOffset"] = 0;
    accessor["bufferView"] = out["bufferViews"].size();
    out["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", append(bin, bytes)}, {"byteLength", bytes.size()}});
  }
  return ok;
}

}  // namespace

bool gltf_is_compressed(const json& document) {
  bool compressed = !for_each_draco_primitive(document, [](size_t, size_t, const json&) {
    return false;  // one is enough
  });
  for (const json& view : array_of(document, "bufferViews"))
    compressed = compressed || json_at(view, {"extensions", "EXT_meshopt_compression"}) != nullptr;
  for (const json& buffer : array_of(document, "buffers"))
    compressed = compressed || is_meshopt_fallback(buffer);
  return compressed;
}

bool decompress_gltf(const json& document, const std::string& folder, const std::string& bin_chunk,
                     json& out, std::string& bin, std::set<int>& draco_accessors,
                     JsonFailure& failure) {
  std::vector<GltfBufferBytes> buffers;
  if (!check_budget(document, failure) ||
      !read_gltf_buffers(document, folder, bin_chunk, buffers, failure))
    return false;
  out = document;
  out["bufferViews"] = json::array();
  bin.clear();
  if (!rewrite_views(document, buffers, out, bin, failure) ||
      !rewrite_draco(document, out, bin, draco_accessors, failure))
    return false;
  out["buffers"] = json::array({{{"byteLength", bin.size()}}});
  return true;
}

}  // namespace gfield
