#include "geometry/gltf_checks.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string_view>
#include <vector>

#include "geometry/gltf_buffers.hpp"
#include "geometry/gltf_extensions.hpp"
#include "gfield/limits.hpp"
#include "gfield/located_json.hpp"

namespace gfield {
namespace {

using nlohmann::json;

/// Every value reached by `pattern` ("a/*/b": "*" is every element of an array or member of an
/// object) from `value` at `pointer`, with its pointer.
void collect(const json& value, std::string_view pattern, const std::string& pointer,
             std::vector<std::pair<const json*, std::string>>& out) {
  if (pattern.empty()) {
    out.emplace_back(&value, pointer);
    return;
  }
  const size_t slash = pattern.find('/');
  const std::string_view part = pattern.substr(0, slash);
  const std::string_view rest = slash == std::string_view::npos ? "" : pattern.substr(slash + 1);
  if (part == "*" && value.is_array()) {
    for (size_t i = 0; i < value.size(); ++i) {
      collect(value[i], rest, json_pointer_child(pointer, i), out);
    }
  } else if (part == "*" && value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) {
      collect(it.value(), rest, json_pointer_child(pointer, it.key()), out);
    }
  } else if (value.is_object() && value.contains(std::string(part))) {
    collect(value[std::string(part)], rest, json_pointer_child(pointer, std::string(part)), out);
  }
}

/// The number of elements of the array at `path` ("" when absent: 0).
size_t array_size(const json& document, std::string_view path) {
  std::vector<std::pair<const json*, std::string>> found;
  collect(document, path, "", found);
  return found.size() == 1 && found[0].first->is_array() ? found[0].first->size() : 0;
}

/// Which index refers to which array.
struct Reference {
  const char* pattern;
  const char* target;
};

constexpr Reference kReferences[] = {
    {"scene", "scenes"},
    {"scenes/*/nodes/*", "nodes"},
    {"nodes/*/children/*", "nodes"},
    {"nodes/*/mesh", "meshes"},
    {"nodes/*/camera", "cameras"},
    {"nodes/*/skin", "skins"},
    {"nodes/*/extensions/KHR_lights_punctual/light", "extensions/KHR_lights_punctual/lights"},
    {"meshes/*/primitives/*/attributes/*", "accessors"},
    {"meshes/*/primitives/*/indices", "accessors"},
    {"meshes/*/primitives/*/material", "materials"},
    {"meshes/*/primitives/*/targets/*/*", "accessors"},
    {"accessors/*/bufferView", "bufferViews"},
    {"accessors/*/sparse/indices/bufferView", "bufferViews"},
    {"accessors/*/sparse/values/bufferView", "bufferViews"},
    {"bufferViews/*/buffer", "buffers"},
    {"bufferViews/*/extensions/EXT_meshopt_compression/buffer", "buffers"},
    {"meshes/*/primitives/*/extensions/KHR_draco_mesh_compression/bufferView", "bufferViews"},
    {"materials/*/pbrMetallicRoughness/baseColorTexture/index", "textures"},
    {"materials/*/pbrMetallicRoughness/metallicRoughnessTexture/index", "textures"},
    {"materials/*/normalTexture/index", "textures"},
    {"materials/*/occlusionTexture/index", "textures"},
    {"materials/*/emissiveTexture/index", "textures"},
    {"materials/*/extensions/*/*/index", "textures"},
    {"textures/*/source", "images"},
    {"textures/*/sampler", "samplers"},
    {"images/*/bufferView", "bufferViews"},
    {"skins/*/joints/*", "nodes"},
    {"skins/*/skeleton", "nodes"},
    {"skins/*/inverseBindMatrices", "accessors"},
    {"animations/*/channels/*/target/node", "nodes"},
    {"animations/*/samplers/*/input", "accessors"},
    {"animations/*/samplers/*/output", "accessors"},
};

/// An index: an integer in [0, size).
bool check_index(const json& value, size_t size, const char* target, std::string& what) {
  const std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  if (!value.is_number_integer()) {
    what = text + " is not an index (an integer from 0) of the " + target;
    return false;
  }
  if (value.get<std::int64_t>() < 0 || std::uint64_t(value.get<std::int64_t>()) >= size) {
    what = "index " + text + " out of range (" + std::to_string(size) + " " + target + ")";
    return false;
  }
  return true;
}

bool check_references(const json& document, JsonFailure& failure) {
  for (const auto& [pattern, target] : kReferences) {
    std::vector<std::pair<const json*, std::string>> found;
    collect(document, pattern, "", found);
    const size_t size = array_size(document, target);
    for (const auto& [value, pointer] : found) {
      if (!check_index(*value, size, target, failure.what)) {
        failure.pointer = pointer;
        return false;
      }
    }
  }
  // Channels name samplers of their own animation.
  std::vector<std::pair<const json*, std::string>> animations;
  collect(document, "animations/*", "", animations);
  for (const auto& [animation, pointer] : animations) {
    std::vector<std::pair<const json*, std::string>> samplers;
    collect(*animation, "channels/*/sampler", pointer, samplers);
    for (const auto& [value, where] : samplers) {
      if (!check_index(*value, array_size(*animation, "samplers"), "samplers", failure.what)) {
        failure.pointer = where;
        return false;
      }
    }
  }
  return true;
}

/// Every top-level array within kMaxGltfElements, the materials within kMaxMeshMaterials (as
/// every mesh format's).
bool check_array_sizes(const json& document, JsonFailure& failure) {
  if (array_size(document, "materials") > kMaxMeshMaterials) {
    failure = {"/materials", std::to_string(array_size(document, "materials")) +
                                 " materials, more than the limit of " +
                                 std::to_string(kMaxMeshMaterials)};
    return false;
  }
  for (auto it = document.begin(); it != document.end(); ++it) {
    if (it.value().is_array() && it.value().size() > kMaxGltfElements) {
      failure = {json_pointer_child("", it.key()), std::to_string(it.value().size()) +
                                                       " elements, more than the limit of " +
                                                       std::to_string(kMaxGltfElements)};
      return false;
    }
  }
  return true;
}

/// The parent of every node (-1: a root) from the nodes' children; false with `failure` for a
/// node that is its own child or is the child of two nodes. One visit per node and per child.
bool node_parents(const json& document, std::vector<std::int64_t>& parent, JsonFailure& failure,
                  std::uint64_t& visits) {
  const size_t nodes = array_size(document, "nodes");
  parent.assign(nodes, -1);
  for (size_t n = 0; n < nodes; ++n) {
    ++visits;
    const json& node = document["nodes"][n];
    if (!node.is_object() || !node.contains("children") || !node["children"].is_array())
      continue;
    const json& children = node["children"];
    for (size_t k = 0; k < children.size(); ++k) {
      ++visits;
      const std::int64_t c = children[k].get<std::int64_t>();
      if (c == std::int64_t(n) || parent[size_t(c)] >= 0) {
        const std::string where = json_pointer_child("/nodes", n);
        failure = {json_pointer_child(json_pointer_child(where, "children"), k),
                   c == std::int64_t(n)
                       ? "node " + std::to_string(c) + " is its own child"
                       : "node " + std::to_string(c) + " is a child of node " +
                             std::to_string(parent[size_t(c)]) + " and of node " +
                             std::to_string(n) + " (a node has one parent at most)"};
        return false;
      }
      parent[size_t(c)] = std::int64_t(n);
    }
  }
  return true;
}

/// With one parent at most per node, the nodes no root reaches lie on or below a cycle: walks
/// from the roots down (each node once), then from an unreached node up to the cycle above it
/// (each node once more). False with `failure` naming the cycle's nodes.
bool check_no_cycle(const json& document, const std::vector<std::int64_t>& parent,
                    JsonFailure& failure, std::uint64_t& visits) {
  const size_t nodes = parent.size();
  std::vector<char> reached(nodes, 0);
  std::vector<size_t> stack;
  for (size_t n = 0; n < nodes; ++n)
    if (parent[n] < 0)
      stack.push_back(n);
  while (!stack.empty()) {
    const size_t n = stack.back();
    stack.pop_back();
    ++visits;
    reached[n] = 1;
    const json& node = document["nodes"][n];
    if (node.is_object() && node.contains("children") && node["children"].is_array())
      for (const json& child : node["children"])
        stack.push_back(child.get<size_t>());
  }
  const auto first = std::find(reached.begin(), reached.end(), 0);
  if (first == reached.end())
    return true;
  // Up from an unreached node: the first node met twice is on the cycle.
  size_t n = size_t(first - reached.begin());
  for (; reached[n] != 2; n = size_t(parent[n])) {
    ++visits;
    reached[n] = 2;
  }
  std::string cycle = std::to_string(n);
  size_t length = 1;
  for (size_t m = size_t(parent[n]); m != n; m = size_t(parent[m]), ++length)
    if (length < 10)
      cycle += ", " + std::to_string(m);
  failure = {json_pointer_child("/nodes", n),
             "the node hierarchy has a cycle of " + std::to_string(length) + " nodes: " + cycle +
                 (length > 10 ? ", ..." : "") +
                 " (each the child of the next, the last of the first)"};
  return false;
}

}  // namespace

bool check_node_forest(const json& document, JsonFailure& failure, std::uint64_t& visits) {
  std::vector<std::int64_t> parent;
  if (!node_parents(document, parent, failure, visits) ||
      !check_no_cycle(document, parent, failure, visits))
    return false;
  std::vector<std::pair<const json*, std::string>> roots;
  collect(document, "scenes/*/nodes/*", "", roots);
  for (const auto& [root, pointer] : roots) {
    if (parent[size_t(root->get<std::int64_t>())] >= 0) {
      failure = {pointer, "a scene lists node " + root->dump() + ", which has a parent"};
      return false;
    }
  }
  return true;
}

namespace {

/// The scheme of `uri` ("file" of "file:///x"), "" for a relative reference (RFC 3986: letters,
/// digits, '+', '-', '.' up to a ':' before any '/', '?' or '#').
std::string uri_scheme(const std::string& uri) {
  const size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0])))
    return "";
  for (size_t i = 1; i < colon; ++i) {
    const char c = uri[i];
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.')
      return "";
  }
  return uri.substr(0, colon);
}

/// Buffer and image URIs: data: URIs, or relative paths inside `folder` (the glTF file's)
/// unless `outside` is kAllowed; checked before any file they name is touched.
bool check_uris(const json& document, const std::string& folder, OutsidePaths outside,
                JsonFailure& failure) {
  std::vector<std::pair<const json*, std::string>> uris;
  collect(document, "buffers/*/uri", "", uris);
  collect(document, "images/*/uri", "", uris);
  for (const auto& [value, pointer] : uris) {
    if (!value->is_string())
      continue;
    const std::string uri = value->get<std::string>();
    const std::string scheme = uri_scheme(uri);
    std::string resolved, problem;
    if (scheme == "data")
      continue;
    if (!scheme.empty()) {
      failure = {pointer, "\"" + uri + "\" is a " + scheme +
                              ": URI (gfield reads relative paths and data: URIs)"};
      return false;
    }
    if (!resolve_named_path(folder, decode_uri(uri), folder, outside, resolved, problem)) {
      failure = {pointer, problem};
      return false;
    }
  }
  return true;
}

/// An unsigned integer member `key` of `object` (`fallback` when absent); false with `failure`
/// when it is not one or above `max`.
bool unsigned_member(const json& object, const std::string& pointer, const char* key,
                     std::uint64_t fallback, std::uint64_t max, std::uint64_t& value,
                     JsonFailure& failure) {
  value = fallback;
  if (!object.is_object() || !object.contains(key)) {
    return true;
  }
  const json& v = object[key];
  if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::uint64_t>() > max) {
    failure = {json_pointer_child(pointer, key),
               "expected an integer in [0, " + std::to_string(max) + "]"};
    return false;
  }
  value = v.get<std::uint64_t>();
  return true;
}

/// Buffers: present on disk with their byteLength (external), within the BIN chunk (.glb).
bool check_buffers(const json& document, const std::string& folder, std::int64_t bin_bytes,
                   std::vector<std::uint64_t>& lengths, JsonFailure& failure) {
  for (size_t b = 0; b < array_size(document, "buffers"); ++b) {
    const json& buffer = document["buffers"][b];
    const std::string pointer = json_pointer_child("/buffers", b);
    std::uint64_t length = 0;
    if (!unsigned_member(buffer, pointer, "byteLength", 0, kMaxMeshFileBytes, length, failure)) {
      return false;
    }
    lengths.push_back(length);
    const bool has_uri = buffer.is_object() && buffer.contains("uri") && buffer["uri"].is_string();
    const std::string uri = has_uri ? buffer["uri"].get<std::string>() : "";
    if (!has_uri && is_meshopt_fallback(buffer)) {
      continue;  // no bytes: EXT_meshopt_compression views decode into it
    }
    if (!has_uri && (bin_bytes < 0 || b > 0 || std::int64_t(length) > bin_bytes)) {
      failure = {pointer, bin_bytes < 0 || b > 0
                              ? "a buffer without a uri (only a .glb's first buffer and "
                                "EXT_meshopt_compression fallback buffers may have none)"
                              : "byteLength " + std::to_string(length) +
                                    " is beyond the BIN chunk's " + std::to_string(bin_bytes) +
                                    " bytes (truncated file?)"};
      return false;
    }
    if (!has_uri || uri.rfind("data:", 0) == 0) {
      continue;
    }
    const std::filesystem::path path = std::filesystem::path(folder) / decode_uri(uri);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      failure = {json_pointer_child(pointer, "uri"), "no such file: " + path.string()};
      return false;
    }
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    if (ec || size != length) {
      failure = {json_pointer_child(pointer, "uri"),
                 path.string() + " holds " + std::to_string(size) + " bytes, byteLength says " +
                     std::to_string(length)};
      return false;
    }
  }
  return true;
}

/// Buffer views within their buffers; `extents` receives each view's byteLength.
bool check_buffer_views(const json& document, const std::vector<std::uint64_t>& buffers,
                        std::vector<std::uint64_t>& lengths, JsonFailure& failure) {
  for (size_t v = 0; v < array_size(document, "bufferViews"); ++v) {
    const json& view = document["bufferViews"][v];
    const std::string pointer = json_pointer_child("/bufferViews", v);
    std::uint64_t offset = 0, length = 0, stride = 0;
    if (!view.is_object() || !view.contains("buffer") || !view.contains("byteLength")) {
      failure = {pointer, "a buffer view needs buffer and byteLength"};
      return false;
    }
    if (!unsigned_member(view, pointer, "byteOffset", 0, kMaxMeshFileBytes, offset, failure) ||
        !unsigned_member(view, pointer, "byteLength", 0, kMaxMeshFileBytes, length, failure) ||
        !unsigned_member(view, pointer, "byteStride", 0, 252, stride, failure)) {
      return false;
    }
    const std::uint64_t buffer = buffers[view["buffer"].get<size_t>()];
    if (offset + length > buffer) {
      failure = {pointer, "bytes " + std::to_string(offset) + " to " +
                              std::to_string(offset + length) + " are beyond its buffer's " +
                              std::to_string(buffer)};
      return false;
    }
    lengths.push_back(length);
  }
  return true;
}

/// Accessors: valid types, within their buffer views.
bool check_accessors(const json& document, const std::vector<std::uint64_t>& views,
                     JsonFailure& failure) {
  for (size_t a = 0; a < array_size(document, "accessors"); ++a) {
    const json& accessor = document["accessors"][a];
    const std::string pointer = json_pointer_child("/accessors", a);
    std::uint64_t offset = 0, count = 0, type_code = 0;
    if (!unsigned_member(accessor, pointer, "byteOffset", 0, kMaxMeshFileBytes, offset, failure) ||
        !unsigned_member(accessor, pointer, "count", 0, std::uint64_t(kMaxMeshVertices), count,
                         failure) ||
        !unsigned_member(accessor, pointer, "componentType", 0, 1u << 16, type_code, failure)) {
      return false;
    }
    const std::uint64_t bytes = gltf_component_bytes(std::int64_t(type_code));
    const std::uint64_t components = accessor.contains("type") && accessor["type"].is_string()
                                         ? gltf_type_components(accessor["type"].get<std::string>())
                                         : 0;
    if (bytes == 0 || components == 0 || count == 0) {
      failure = {pointer,
                 "an accessor needs a componentType, a type (SCALAR ... MAT4) and a "
                 "count of at least 1"};
      return false;
    }
    if (!accessor.contains("bufferView")) {
      continue;
    }
    const json& view = document["bufferViews"][accessor["bufferView"].get<size_t>()];
    const std::uint64_t element = bytes * components;
    const std::uint64_t stride = view.value("byteStride", std::uint64_t(0));
    if (stride != 0 && stride < element) {
      failure = {pointer, "its buffer view's byteStride " + std::to_string(stride) +
                              " is below the element's " + std::to_string(element) + " bytes"};
      return false;
    }
    const std::uint64_t end = offset + (stride ? stride : element) * (count - 1) + element;
    const std::uint64_t length = views[accessor["bufferView"].get<size_t>()];
    if (end > length) {
      failure = {pointer, std::to_string(count) + " elements end at byte " + std::to_string(end) +
                              ", beyond its buffer view's " + std::to_string(length)};
      return false;
    }
  }
  return true;
}

}  // namespace

std::uint64_t gltf_component_bytes(std::int64_t type) {
  switch (type) {
    case 5120:
    case 5121:
      return 1;
    case 5122:
    case 5123:
      return 2;
    case 5125:
    case 5126:
      return 4;
    default:
      return 0;
  }
}

std::uint64_t gltf_type_components(const std::string& type) {
  const std::pair<const char*, std::uint64_t> kTypes[] = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT2", 4}, {"MAT3", 9}, {"MAT4", 16}};
  for (const auto& [name, n] : kTypes) {
    if (type == name) {
      return n;
    }
  }
  return 0;
}

std::string decode_uri(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    const auto hex = [](char c) {
      return c >= '0' && c <= '9'   ? c - '0'
             : c >= 'a' && c <= 'f' ? c - 'a' + 10
             : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                    : -1;
    };
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

bool check_gltf_json(const nlohmann::json& document, const std::string& folder,
                     std::int64_t bin_bytes, OutsidePaths outside, JsonFailure& failure) {
  if (!document.is_object()) {
    failure = {"", "the document is not a JSON object"};
    return false;
  }
  std::vector<std::uint64_t> buffers, views;
  std::uint64_t visits = 0;
  return check_required_extensions(document, failure) && check_array_sizes(document, failure) &&
         check_references(document, failure) && check_node_forest(document, failure, visits) &&
         check_uris(document, folder, outside, failure) &&
         check_buffers(document, folder, bin_bytes, buffers, failure) &&
         check_buffer_views(document, buffers, views, failure) &&
         check_accessors(document, views, failure);
}

}  // namespace gfield
