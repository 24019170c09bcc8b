#include "geometry/gltf_document.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <limits>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "geometry/glb_container.hpp"
#include "geometry/gltf_checks.hpp"
#include "geometry/gltf_decompress.hpp"
#include "geometry/gltf_mesh.hpp"
#include "gfield/file_read.hpp"
#include "gfield/limits.hpp"
#include "gfield/located_json.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

/// tinygltf's file access: only below the glTF file's folder (unless outside paths are
/// allowed), at most kMaxMeshFileBytes. The URIs were checked before (gltf_checks.hpp); this
/// holds whatever tinygltf makes of them.
struct FileAccess {
  std::string folder;  ///< with a trailing separator
  OutsidePaths outside = OutsidePaths::kRefused;
};

bool file_exists(const std::string& path, void* user) {
  const auto* access = static_cast<const FileAccess*>(user);
  std::error_code ec;
  return (access->outside == OutsidePaths::kAllowed || path_is_inside(access->folder, path)) &&
         fs::is_regular_file(path, ec);
}

std::string expand_path(const std::string& path, void*) {
  return path;
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void*) {
  std::string data;
  if (!read_file(path, kMaxMeshFileBytes, data, *err)) {
    return false;
  }
  out->assign(data.begin(), data.end());
  return true;
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "gfield does not write through tinygltf";
  return false;
}

/// Keeps an embedded image's bytes as they are (gfield decodes them: mesh textures). The byte
/// range was checked against its buffer before tinygltf read the file.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

/// tinygltf's first error line, printable.
std::string first_line(const std::string& text) {
  return printable(text.substr(0, text.find('\n')));
}

bool parse_with_tinygltf(const std::string& data, const std::string& json, bool binary,
                         GltfDocument& document, std::string& error) {
  FileAccess access{(fs::absolute(document.file).parent_path() / "").string(),
                    document.outside_paths};
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, nullptr);
  loader.SetFsCallbacks({file_exists, expand_path, read_whole_file, refuse_write, &access});
  std::string err, warn;
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&document.model, &err, &warn,
                                           reinterpret_cast<const unsigned char*>(data.data()),
                                           unsigned(data.size()), access.folder)
             : loader.LoadASCIIFromString(&document.model, &err, &warn, json.data(),
                                          unsigned(json.size()), access.folder);
  if (!ok) {
    error = document.file + ": " + (err.empty() ? "tinygltf refused the file" : first_line(err));
    return false;
  }
  return true;
}

/// "FILE:LINE:COLUMN: POINTER: what" for `failure`, located in `located`.
std::string located_failure(const std::string& filename, const LocatedJson& located,
                            const JsonFailure& failure) {
  const JsonLocation where = located.at(failure.pointer);
  return filename + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) + ": " +
         printable(failure.pointer + ": " + failure.what);
}

}  // namespace

bool load_gltf_document(const std::string& filename, OutsidePaths outside, GltfDocument& document,
                        std::string& error) {
  std::string data, json;
  if (!read_file(filename, kMaxMeshFileBytes, data, error)) {
    return false;
  }
  std::string extension = fs::path(filename).extension().string();
  for (char& c : extension)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  const bool binary = extension == ".glb" || data.compare(0, 4, "glTF") == 0;
  std::int64_t bin_bytes = -1;
  std::uint64_t bin_offset = 0;
  if (binary && !read_glb_container(data, json, bin_offset, bin_bytes, error)) {
    error = filename + ": " + error;
    return false;
  }
  LocatedJson located;
  std::string parse_error;
  if (!parse_located_json(binary ? json : data, located, parse_error)) {
    error = filename + ":" + printable(parse_error);
    return false;
  }
  const std::string folder = fs::path(filename).parent_path().string();
  JsonFailure failure;
  if (!check_gltf_json(located.value, folder, bin_bytes, outside, failure)) {
    error = located_failure(filename, located, failure);
    return false;
  }
  document = GltfDocument{};
  document.file = filename;
  document.outside_paths = outside;
  if (!gltf_is_compressed(located.value)) {
    document.json = std::move(located.value);
    return parse_with_tinygltf(data, binary ? json : data, binary, document, error);
  }
  // Draco and meshopt: decoded into one buffer, checked again, read as a .glb.
  std::string bin;
  const std::string chunk = binary ? data.substr(size_t(bin_offset), size_t(bin_bytes)) : "";
  if (!decompress_gltf(located.value, folder, chunk, document.json, bin, document.draco_accessors,
                       failure) ||
      !check_gltf_json(document.json, folder, std::int64_t(bin.size()), outside, failure)) {
    error = located_failure(filename, located, failure);
    return false;
  }
  return parse_with_tinygltf(
      glb_bytes(document.json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), bin),
      "", true, document, error);
}

std::vector<std::string> gltf_external_files(const std::string& filename, OutsidePaths outside) {
  std::string data, json, ignored;
  std::int64_t bin_bytes = 0;
  std::uint64_t bin_offset = 0;
  if (!read_file(filename, kMaxMeshFileBytes, data, ignored) ||
      (data.compare(0, 4, "glTF") == 0 &&
       !read_glb_container(data, json, bin_offset, bin_bytes, ignored))) {
    return {};
  }
  const nlohmann::json document = nlohmann::json::parse(json.empty() ? data : json, nullptr, false);
  std::vector<std::string> files;
  for (const char* kind : {"buffers", "images"}) {
    if (!document.is_object() || !document.contains(kind) || !document[kind].is_array())
      continue;
    for (const nlohmann::json& item : document[kind]) {
      const nlohmann::json* uri = json_at(item, {"uri"});
      const fs::path folder = fs::path(filename).parent_path();
      std::string file, problem;
      if (uri != nullptr && uri->is_string() && uri->get<std::string>().rfind("data:", 0) != 0 &&
          resolve_named_path(folder, decode_uri(uri->get<std::string>()), folder, outside, file,
                             problem))
        files.push_back(file);
    }
  }
  return files;
}

int accessor_components(const tinygltf::Accessor& accessor) {
  switch (accessor.type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT2:
      return 4;
    case TINYGLTF_TYPE_MAT3:
      return 9;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 1;
  }
}

namespace {

/// A stored component `value` of glTF component type `type` as it reads when normalized
/// (glTF 2.0, "Animations": signed types clamped to -1).
double normalized_value(double value, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return std::max(value / 127.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return value / 255.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return std::max(value / 32767.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return value / 65535.0;
    default:
      return value;
  }
}

/// One component at `base` of `accessor` as a double (normalised when asked).
double component(const unsigned char* base, const tinygltf::Accessor& accessor) {
  const auto load = [&](auto v) {
    std::memcpy(&v, base, sizeof(v));
    return double(v);
  };
  double value = 0.0;
  switch (accessor.componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      value = load(std::int8_t());
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      value = load(std::uint8_t());
      break;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      value = load(std::int16_t());
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      value = load(std::uint16_t());
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      value = load(std::uint32_t());
      break;
    default:
      value = load(float());
  }
  return accessor.normalized ? normalized_value(value, accessor.componentType) : value;
}

/// Calls visit(element, component, value) for every value of accessor `index` (zeros without a
/// buffer view; sparse accessors are refused by the callers).
template <class Visit>
void for_each_value(const GltfDocument& document, int index, Visit visit) {
  const tinygltf::Accessor& accessor = document.model.accessors[size_t(index)];
  const int components = accessor_components(accessor);
  if (accessor.bufferView < 0) {
    for (size_t e = 0; e < accessor.count; ++e)
      for (int k = 0; k < components; ++k)
        visit(e, k, 0.0);
    return;
  }
  const tinygltf::BufferView& view = document.model.bufferViews[size_t(accessor.bufferView)];
  const tinygltf::Buffer& buffer = document.model.buffers[size_t(view.buffer)];
  const size_t bytes = size_t(tinygltf::GetComponentSizeInBytes(accessor.componentType));
  const size_t stride = view.byteStride ? view.byteStride : bytes * size_t(components);
  const unsigned char* base = buffer.data.data() + view.byteOffset + accessor.byteOffset;
  for (size_t e = 0; e < accessor.count; ++e)
    for (int k = 0; k < components; ++k)
      visit(e, k, component(base + e * stride + size_t(k) * bytes, accessor));
}

}  // namespace

std::vector<float> read_accessor_floats(const GltfDocument& document, int index) {
  const tinygltf::Accessor& accessor = document.model.accessors[size_t(index)];
  const int components = accessor_components(accessor);
  std::vector<float> values(accessor.count * size_t(components));
  for_each_value(document, index, [&](size_t e, int k, double v) {
    values[e * size_t(components) + size_t(k)] = float(v);
  });
  return values;
}

std::vector<std::int64_t> read_accessor_integers(const GltfDocument& document, int index) {
  const tinygltf::Accessor& accessor = document.model.accessors[size_t(index)];
  std::vector<std::int64_t> values(accessor.count);
  // An accessor of floats may hold any value: one no int64 can hold becomes -1, an index out of
  // range for whoever checks it (converting it would be undefined behaviour).
  for_each_value(document, index, [&](size_t e, int k, double v) {
    const bool representable = v > -9.0e18 && v < 9.0e18;
    values[e] = k != 0 ? 0 : representable ? std::int64_t(v) : -1;
  });
  return values;
}

glm::dmat4 node_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        m[c][r] = node.matrix[size_t(c * 4 + r)];
    return m;
  }
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3)
    m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  if (node.rotation.size() == 4) {  // x, y, z, w
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    m = m * glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3)
    m = m * glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

bool scene_nodes(const GltfDocument& document, std::vector<PlacedNode>& placed,
                 std::string& error) {
  const tinygltf::Model& model = document.model;
  std::vector<int> roots;
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (size_t(scene) < model.scenes.size()) {
    roots = model.scenes[size_t(scene)].nodes;
  } else {
    std::vector<char> child(model.nodes.size(), 0);
    for (const tinygltf::Node& node : model.nodes)
      for (int c : node.children)
        child[size_t(c)] = 1;
    for (size_t n = 0; n < model.nodes.size(); ++n)
      if (!child[n])
        roots.push_back(int(n));
  }
  placed.clear();
  for (const int root : roots)
    placed.push_back({root, node_matrix(model.nodes[size_t(root)])});
  // Breadth-first: the forest was checked (no cycle, one parent each); a scene may list a root
  // more than once, so the count is bounded.
  for (size_t next = 0; next < placed.size(); ++next) {
    const PlacedNode parent = placed[next];
    for (const int child : model.nodes[size_t(parent.node)].children)
      placed.push_back({child, parent.world * node_matrix(model.nodes[size_t(child)])});
    if (placed.size() > kMaxGltfElements) {
      error = document.file + ": the scene places more than " + std::to_string(kMaxGltfElements) +
              " nodes";
      return false;
    }
  }
  return true;
}

void position_bounds(const std::vector<float>& xyz, glm::dvec3& lo, glm::dvec3& hi) {
  lo = glm::dvec3(std::numeric_limits<double>::max());
  hi = -lo;
  for (size_t v = 0; v + 2 < xyz.size(); v += 3) {
    const glm::dvec3 p(xyz[v], xyz[v + 1], xyz[v + 2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
}

void check_declared_bounds(const GltfDocument& document, int index, const glm::dvec3& lo,
                           const glm::dvec3& hi, std::vector<std::string>& warnings) {
  const tinygltf::Accessor& a = document.model.accessors[size_t(index)];
  if (document.draco_accessors.count(index))
    return;
  const auto text = [](const glm::dvec3& v) {
    return "[" + double_text(v.x) + ", " + double_text(v.y) + ", " + double_text(v.z) + "]";
  };
  for (const auto& [key, declared, data] :
       {std::tuple{"max", &a.maxValues, hi}, std::tuple{"min", &a.minValues, lo}}) {
    if (declared->size() != 3)
      continue;
    const glm::dvec3 stored((*declared)[0], (*declared)[1], (*declared)[2]);
    glm::dvec3 value = stored;
    for (int k = 0; k < 3 && a.normalized; ++k)
      value[k] = normalized_value(stored[k], a.componentType);
    // Exporters round; a float's value printed to 7 digits is off by 1e-7 of it.
    const glm::dvec3 scale = glm::max(hi - lo, glm::max(glm::abs(lo), glm::abs(hi)));
    if (glm::all(glm::lessThanEqual(glm::abs(value - data), 1e-5 * scale)))
      continue;
    warnings.push_back(document.file + ": " +
                       json_pointer_child(json_pointer_child("/accessors", size_t(index)), key) +
                       ": declares " + text(stored) +
                       (a.normalized ? " (normalized " + text(value) + ")" : "") +
                       ", the data reach " + text(data) + " (gfield uses the bounds of the data)");
    return;
  }
}

bool uses_extension(const GltfDocument& document, const char* name) {
  const nlohmann::json* used = json_at(document.json, {"extensionsUsed"});
  return used != nullptr && used->is_array() &&
         std::find(used->begin(), used->end(), nlohmann::json(name)) != used->end();
}

const nlohmann::json* json_at(const nlohmann::json& object,
                              std::initializer_list<const char*> keys) {
  const nlohmann::json* value = &object;
  for (const char* key : keys) {
    if (!value->is_object() || !value->contains(key))
      return nullptr;
    value = &(*value)[key];
  }
  return value;
}

bool number_at(const nlohmann::json& object, std::initializer_list<const char*> keys,
               double fallback, double lo, double hi, const char* range, double& value,
               std::string& what) {
  const nlohmann::json* v = json_at(object, keys);
  value = v != nullptr && v->is_number() ? v->get<double>() : fallback;
  if (!(value >= lo && value <= hi)) {
    for (const char* key : keys) {
      what += what.empty() ? "" : ".";
      what += key;
    }
    what += std::string(" must be in ") + range + " (is " + double_text(value) + ")";
    return false;
  }
  return true;
}

}  // namespace gfield
