#include "geometry/gltf_writer.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/atomic_file.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kBakedTextureSize = 1024;

/// The document and its binary chunk as they grow.
class GlbBuilder {
 public:
  json doc = {{"asset", {{"version", "2.0"}, {"generator", "gfield export-gltf"}}}, {"scene", 0}};
  std::string bin;

  /// A buffer view of `bytes` (4-byte aligned in the BIN chunk); its index.
  int add_view(const void* bytes, size_t size, int target) {
    while (bin.size() % 4 != 0)
      bin += '\0';
    json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
    if (target != 0)
      view["target"] = target;
    bin.append(static_cast<const char*>(bytes), size);
    return push("bufferViews", view);
  }
  /// An accessor of `count` floats of `type` (VEC2, VEC3, VEC4) or unsigned ints (SCALAR).
  template <class T>
  int add_accessor(const std::vector<T>& data, const char* type, int target) {
    json accessor = {{"bufferView", add_view(data.data(), data.size() * sizeof(T), target)},
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
  int push(const char* array, json value) {
    doc[array].push_back(std::move(value));
    return int(doc[array].size()) - 1;
  }
  /// The .glb bytes: header, JSON chunk (padded with spaces), BIN chunk (padded with zeros).
  std::string glb() {
    if (!bin.empty())
      doc["buffers"] = json::array({{{"byteLength", bin.size()}}});
    std::string text = doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    while (text.size() % 4 != 0)
      text += ' ';
    while (bin.size() % 4 != 0)
      bin += '\0';
    std::string out = "glTF";
    const auto u32 = [&](std::uint32_t v) {
      for (int k = 0; k < 4; ++k)
        out += char((v >> (8 * k)) & 0xFF);
    };
    const size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
    u32(2);
    u32(std::uint32_t(total));
    u32(std::uint32_t(text.size()));
    u32(0x4E4F534Au);
    out += text;
    if (!bin.empty()) {
      u32(std::uint32_t(bin.size()));
      u32(0x004E4942u);
      out += bin;
    }
    return out;
  }
};

json vec(glm::vec3 v) {
  return {v.x, v.y, v.z};
}

/// The glTF material of a surface of object material `m` with base colour `base` (the mesh
/// material's factor) and texture `texture` (-1: none).
json material_json(const Material& m, glm::vec3 base, int texture) {
  json pbr = {{"metallicFactor", 0.0}, {"roughnessFactor", 1.0}};
  json out = {{"doubleSided", true}};
  if (m.type == MaterialType::kMirror) {
    pbr = {{"metallicFactor", 1.0}, {"roughnessFactor", 0.0}};
    base = m.color;
  } else if (m.type == MaterialType::kDielectric) {
    pbr["roughnessFactor"] = 0.0;
    base = glm::vec3(1.0f);
    out["extensions"] = {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                         {"KHR_materials_ior", {{"ior", m.ior}}}};
    if (glm::any(glm::greaterThan(m.absorption, glm::vec3(0.0f))))
      out["extensions"]["KHR_materials_volume"] = {
          {"thicknessFactor", 1.0},
          {"attenuationDistance", 1.0},
          {"attenuationColor", vec(glm::exp(-m.absorption))}};
  }
  pbr["baseColorFactor"] = {base.x, base.y, base.z, 1.0};
  if (texture >= 0)
    pbr["baseColorTexture"] = {{"index", texture}};
  out["pbrMetallicRoughness"] = pbr;
  return out;
}

/// The vertices of a mesh file: one per (vertex, texture coordinate) pair; the indices of the
/// faces of each material (-1: none) into them.
struct ExportedMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec4> colors;
  std::map<int, std::vector<std::uint32_t>> faces;  ///< by material
};

ExportedMesh exported_mesh(const TriangleMesh& mesh, const MeshAppearance& a) {
  ExportedMesh out;
  std::map<std::pair<int, std::pair<float, float>>, std::uint32_t> index;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    std::vector<std::uint32_t>& faces =
        out.faces[a.face_material.empty() ? -1 : a.face_material[f]];
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.triangles[f][c];
      const glm::vec2 uv = a.corner_uv.empty() ? glm::vec2(0.0f) : a.corner_uv[3 * f + size_t(c)];
      const auto [it, added] = index.emplace(std::make_pair(v, std::make_pair(uv.x, uv.y)),
                                             std::uint32_t(out.positions.size()));
      if (added) {
        out.positions.push_back(glm::vec3(mesh.positions[size_t(v)]));
        out.uvs.emplace_back(uv.x, 1.0f - uv.y);  // glTF: v down
        if (!a.vertex_color.empty())
          out.colors.emplace_back(a.vertex_color[size_t(v)], 1.0f);
      }
      faces.push_back(it->second);
    }
  }
  return out;
}

/// Accessors of an exported mesh's vertices: POSITION (with min, max), TEXCOORD_0, COLOR_0.
json vertex_attributes(GlbBuilder& b, const ExportedMesh& m, bool textured) {
  json attributes;
  attributes["POSITION"] = b.add_accessor(m.positions, "VEC3", kArrayBuffer);
  glm::vec3 lo(3e38f), hi(-3e38f);
  for (const glm::vec3& p : m.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  b.doc["accessors"][attributes["POSITION"].get<size_t>()]["min"] = vec(lo);
  b.doc["accessors"][attributes["POSITION"].get<size_t>()]["max"] = vec(hi);
  if (textured)
    attributes["TEXCOORD_0"] = b.add_accessor(m.uvs, "VEC2", kArrayBuffer);
  if (!m.colors.empty())
    attributes["COLOR_0"] = b.add_accessor(m.colors, "VEC4", kArrayBuffer);
  return attributes;
}

/// What the meshes of the scene became: per mesh asset and kind (own base colour or not), its
/// vertex accessors; per mesh asset's texture, the glTF texture; per object material, the mesh.
struct ExportCache {
  std::map<std::pair<int, bool>, json> attributes;
  std::map<std::pair<int, int>, int> textures;
  std::map<std::string, int> meshes;  ///< key: mesh asset and material (JSON)
};

/// The glTF mesh of a mesh object: its file's triangles, one primitive per material.
bool export_mesh(GlbBuilder& b, const Scene& scene, const SceneObject& o, ExportCache& cache,
                 int& mesh_index, std::string& error) {
  const MeshAsset& asset = scene.meshes[size_t(o.shape.mesh)];
  const Material& material = o.material;
  const bool own = material.texture == TextureType::kMesh;
  const std::string key = json{o.shape.mesh,        int(material.type), int(material.texture),
                               vec(material.color), material.ior,       vec(material.absorption)}
                              .dump(-1, ' ', false, json::error_handler_t::replace);
  if (const auto found = cache.meshes.find(key); found != cache.meshes.end()) {
    mesh_index = found->second;
    return true;
  }
  TriangleMesh mesh;
  MeshAppearance a;
  std::vector<std::string> warnings;
  if (!load_mesh(MeshSource{asset.file, asset.part, asset.outside_paths}, mesh, &a, warnings,
                 error))
    return false;
  const ExportedMesh m = exported_mesh(mesh, own ? a : MeshAppearance{});
  json& attributes = cache.attributes[{o.shape.mesh, own}];
  if (attributes.is_null())
    attributes = vertex_attributes(b, m, own && !a.corner_uv.empty());
  json primitives = json::array();
  for (const auto& [mi, faces] : m.faces) {
    glm::vec3 base = material.color;
    int texture = -1;
    if (mi >= 0) {
      base *= a.materials[size_t(mi)].factor;
      const int t = a.materials[size_t(mi)].texture;
      const std::pair<int, int> texture_key(o.shape.mesh, t);
      std::string png;
      if (t >= 0 && !cache.textures.count(texture_key) &&
          !encode_png(a.textures[size_t(t)].image, png)) {
        error = asset.file + ": cannot encode its texture as PNG";
        return false;
      }
      if (t >= 0 && !cache.textures.count(texture_key))
        cache.textures[texture_key] = b.add_png_texture(png);
      texture = t >= 0 ? cache.textures[texture_key] : -1;
    }
    if (glm::any(glm::greaterThan(base, glm::vec3(1.0f)))) {
      error = asset.file + ": a base colour above 1 (glTF's baseColorFactor ends at 1)";
      return false;
    }
    primitives.push_back({{"attributes", attributes},
                          {"indices", b.add_accessor(faces, "SCALAR", kElementArrayBuffer)},
                          {"material", b.push("materials", material_json(material, base, texture))},
                          {"mode", 4}});
  }
  mesh_index = b.push("meshes",
                      {{"name", fs::path(asset.file).stem().string()}, {"primitives", primitives}});
  cache.meshes[key] = mesh_index;
  return true;
}

/// The glTF mesh of a quad: two triangles, its procedural texture baked.
bool export_quad(GlbBuilder& b, const SceneObject& o, int& mesh_index, std::string& error) {
  const glm::vec2 h(0.5f * o.shape.size.x, 0.5f * o.shape.size.y);
  ExportedMesh m;
  m.positions = {{-h.x, -h.y, 0.0f}, {h.x, -h.y, 0.0f}, {h.x, h.y, 0.0f}, {-h.x, h.y, 0.0f}};
  m.uvs = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
  m.faces[0] = {0, 1, 2, 0, 2, 3};
  const bool baked =
      o.material.type == MaterialType::kDiffuse && o.material.texture != TextureType::kNone;
  int texture = -1;
  if (baked) {
    Image image(kBakedTextureSize, kBakedTextureSize);
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        image.at(x, y) =
            texture_albedo(o.material, glm::vec2((float(x) + 0.5f) / float(image.width),
                                                 1.0f - (float(y) + 0.5f) / float(image.height)));
    std::string png;
    if (!encode_png(image, png)) {
      error = "cannot encode a baked texture as PNG";
      return false;
    }
    texture = b.add_png_texture(png);
  }
  const glm::vec3 base = baked ? glm::vec3(1.0f) : o.material.color;
  const json attributes = vertex_attributes(b, m, baked);
  json primitive = {{"attributes", attributes},
                    {"indices", b.add_accessor(m.faces[0], "SCALAR", kElementArrayBuffer)},
                    {"material", b.push("materials", material_json(o.material, base, texture))},
                    {"mode", 4}};
  mesh_index = b.push("meshes", {{"name", o.name}, {"primitives", json::array({primitive})}});
  return true;
}

/// A node's translation, rotation (quaternion x, y, z, w) and scale from a Transform.
json node_transform(const Transform& t) {
  const glm::dmat4 m = object_to_world(t);
  const glm::dmat3 rotation =
      glm::dmat3(m) * glm::dmat3(glm::scale(glm::dmat4(1.0), 1.0 / glm::dvec3(t.scale)));
  const glm::dquat q = glm::normalize(glm::quat_cast(rotation));
  return {{"translation", vec(t.translate)},
          {"rotation", {q.x, q.y, q.z, q.w}},
          {"scale", vec(t.scale)}};
}

/// The camera's node (and its camera).
json camera_node(GlbBuilder& b, const Scene& scene) {
  const Camera& c = scene.camera;
  const glm::dmat4 world =
      glm::inverse(glm::lookAt(glm::dvec3(c.position), glm::dvec3(c.target), glm::dvec3(c.up)));
  const glm::dquat q = glm::normalize(glm::quat_cast(glm::dmat3(world)));
  const int camera =
      b.push("cameras", {{"type", "perspective"},
                         {"perspective",
                          {{"yfov", glm::radians(double(c.fov_degrees))},
                           {"aspectRatio", double(scene.width) / double(scene.height)},
                           {"znear", 1e-3}}}});
  return {{"name", "camera"},
          {"camera", camera},
          {"translation", vec(c.position)},
          {"rotation", {q.x, q.y, q.z, q.w}}};
}

/// A light's node (and its KHR_lights_punctual light).
json light_node(GlbBuilder& b, const Light& l) {
  json& lights = b.doc["extensions"]["KHR_lights_punctual"]["lights"];
  lights.push_back({{"type", l.type == LightType::kDirectional ? "directional" : "point"},
                    {"color", vec(l.color)},
                    {"intensity", l.intensity}});
  json node = {{"extensions", {{"KHR_lights_punctual", {{"light", lights.size() - 1}}}}}};
  if (l.type == LightType::kPoint) {
    node["translation"] = vec(l.position);
  } else {
    const glm::quat q = glm::rotation(glm::vec3(0.0f, 0.0f, -1.0f), glm::normalize(l.direction));
    node["rotation"] = {q.x, q.y, q.z, q.w};
  }
  return node;
}

/// The scene's settings as the reader takes them back (gltf_scene.hpp): extras "gfield".
json scene_extras(const Scene& scene, const std::string& filename) {
  const EnvironmentDesc& e = scene.environment;
  const char* types[] = {"studio", "constant", "equirect", "cube"};
  json environment = {{"type", types[int(e.type)]}, {"intensity", e.intensity}};
  const fs::path folder = fs::absolute(filename).parent_path();
  const auto relative = [&](const std::string& file) {
    return fs::absolute(file).lexically_relative(folder).string();
  };
  if (e.type == EnvironmentType::kConstant)
    environment["color"] = vec(e.color);
  if (e.type == EnvironmentType::kEquirect)
    environment["file"] = relative(e.file);
  for (size_t f = 0; e.type == EnvironmentType::kCube && f < 6; ++f)
    environment["faces"].push_back(relative(e.faces[f]));
  return {{"purpose", scene.purpose},
          {"image", {{"width", scene.width}, {"height", scene.height}}},
          {"environment", environment},
          {"ambient", vec(scene.ambient)}};
}

/// The extensions the document uses: lights, and those of its materials.
json extensions_used(const json& doc) {
  std::set<std::string> used;
  if (doc.contains("extensions"))
    used.insert("KHR_lights_punctual");
  for (const json& m : doc.value("materials", json::array())) {
    const json extensions = m.value("extensions", json::object());  // items() only refers to it
    for (const auto& [name, value] : extensions.items())
      used.insert(name);
  }
  return json(used);
}

}  // namespace

bool write_gltf_scene(const Scene& scene, const std::string& filename, std::string& error) {
  GlbBuilder b;
  json nodes = json::array({camera_node(b, scene)});
  ExportCache cache;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    int mesh = -1;
    const bool ok = o.shape.type == ShapeType::kMesh ? export_mesh(b, scene, o, cache, mesh, error)
                    : o.shape.type == ShapeType::kQuad
                        ? export_quad(b, o, mesh, error)
                        : (error = std::string("a ") + shape_name(o.shape.type) +
                                   " cannot be exported (meshes and quads only)",
                           false);
    if (!ok) {
      error = filename + ": objects[" + std::to_string(k) + "]: " + error;
      return false;
    }
    json node = node_transform(o.transform);
    node["name"] = o.name;
    node["mesh"] = mesh;
    nodes.push_back(node);
  }
  for (const Light& l : scene.lights)
    nodes.push_back(light_node(b, l));
  json roots = json::array();
  for (size_t n = 0; n < nodes.size(); ++n)
    roots.push_back(n);
  b.doc["nodes"] = nodes;
  b.doc["scenes"] =
      json::array({{{"nodes", roots}, {"extras", {{"gfield", scene_extras(scene, filename)}}}}});
  b.doc["extensionsUsed"] = extensions_used(b.doc);
  return write_text_file(filename, b.glb(), error);
}

}  // namespace gfield
