#include "geometry/gltf_writer.hpp"

#include <filesystem>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "geometry/glb_builder.hpp"
#include "geometry/gltf_export_objects.hpp"
#include "geometry/shape_tessellation.hpp"
#include "gfield/atomic_file.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

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

/// The extensions the document uses: lights, those of its materials and of their base colour
/// textures (KHR_texture_transform).
std::set<std::string> extensions_used(const json& doc) {
  std::set<std::string> used;
  if (doc.contains("extensions"))
    used.insert("KHR_lights_punctual");
  for (const json& m : doc.value("materials", json::array())) {
    const json extensions = m.value("extensions", json::object());  // items() only refers to it
    for (const auto& [name, value] : extensions.items())
      used.insert(name);
    if (m.contains("pbrMetallicRoughness") &&
        m["pbrMetallicRoughness"].contains("baseColorTexture") &&
        m["pbrMetallicRoughness"]["baseColorTexture"].contains("extensions"))
      used.insert("KHR_texture_transform");
  }
  return used;
}

}  // namespace

bool write_gltf_scene(const Scene& scene, const std::string& filename,
                      const GltfExportOptions& options, std::string& error) {
  if (options.segments < kMinShapeSegments || options.segments > kMaxShapeSegments) {
    error = "segments " + std::to_string(options.segments) + " out of range [" +
            std::to_string(kMinShapeSegments) + ", " + std::to_string(kMaxShapeSegments) + "]";
    return false;
  }
  GlbBuilder b;
  json nodes = json::array({camera_node(b, scene)});
  GltfExportCache cache;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    int mesh = -1;
    if (!export_object_mesh(b, scene, o, options.segments, cache, mesh, error)) {
      error = scene.filename + ": objects[" + std::to_string(k) + "]" +
              (o.name.empty() ? "" : " '" + printable(o.name) + "'") + ": " + error;
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
  const std::set<std::string> used = extensions_used(b.doc);
  b.doc["extensionsUsed"] = used;
  // A repeated checker reads wrong without its transform: a reader must implement it.
  if (used.count("KHR_texture_transform"))
    b.doc["extensionsRequired"] = {"KHR_texture_transform"};
  return write_text_file(filename, b.glb(), error);
}

}  // namespace gfield
