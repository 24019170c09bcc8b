#include "geometry/gltf_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include <glm/gtx/compatibility.hpp>

#include "geometry/gltf_document.hpp"
#include "geometry/gltf_mesh.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// A number of the document at `keys` below `object` (`fallback` when absent), within [lo, hi].
bool number_at(const json& object, std::initializer_list<const char*> keys, double fallback,
               double lo, double hi, double& value, std::string& what) {
  const json* v = json_at(object, keys);
  value = v != nullptr && v->is_number() ? v->get<double>() : fallback;
  if (!(value >= lo && value <= hi)) {
    what = std::string(*(keys.end() - 1)) + " " + std::to_string(value) + " is not in [" +
           std::to_string(lo) + ", " + std::to_string(hi) + "]";
    return false;
  }
  return true;
}

/// The gfield material of glTF material `index` (-1: the default, white diffuse).
bool object_material(const GltfDocument& d, int index, Material& m, std::string& what) {
  m = Material{};
  m.type = MaterialType::kDiffuse;
  m.texture = TextureType::kMesh;
  m.color = glm::vec3(1.0f);
  if (index < 0)
    return true;
  const json& g = d.json["materials"][size_t(index)];
  const tinygltf::PbrMetallicRoughness& pbr = d.model.materials[size_t(index)].pbrMetallicRoughness;
  double transmission = 0.0, ior = 1.5, distance = 0.0;
  if (!number_at(g, {"extensions", "KHR_materials_transmission", "transmissionFactor"}, 0.0, 0.0,
                 1.0, transmission, what) ||
      !number_at(g, {"extensions", "KHR_materials_ior", "ior"}, 1.5, 1e-6, 1e6, ior, what) ||
      !number_at(g, {"extensions", "KHR_materials_volume", "attenuationDistance"}, 1e300, 1e-15,
                 1e300, distance, what)) {
    return false;
  }
  glm::vec3 base(1.0f);
  for (size_t k = 0; k < 3 && k < pbr.baseColorFactor.size(); ++k)
    base[int(k)] = float(std::clamp(pbr.baseColorFactor[k], 0.0, kMaxColorComponent));
  if (transmission > 0.0) {
    m.type = MaterialType::kDielectric;
    m.texture = TextureType::kNone;
    m.ior = float(ior);
    const json* c = json_at(g, {"extensions", "KHR_materials_volume", "attenuationColor"});
    for (int k = 0; k < 3 && c != nullptr && c->is_array() && size_t(k) < c->size(); ++k) {
      const double color = (*c)[size_t(k)].is_number() ? (*c)[size_t(k)].get<double>() : 1.0;
      m.absorption[k] =
          float(std::clamp(-std::log(std::max(color, 1e-300)) / distance, 0.0, kMaxColorComponent));
    }
  } else if (pbr.metallicFactor >= 1.0 && pbr.roughnessFactor <= 0.05) {
    m.type = MaterialType::kMirror;
    m.texture = TextureType::kNone;
    m.color = base;
  }
  return true;
}

/// A node's world matrix (after `placement`) as a Transform; a shear is dropped with a warning.
bool place(const glm::dmat4& world, const std::string& what_node, Transform& t,
           std::vector<std::string>& warnings, std::string& error) {
  double residual = 0.0;
  if (!transform_from_matrix(world, t, residual)) {
    error = what_node + ": a mirroring or singular transform (gfield needs positive scales)";
    return false;
  }
  if (glm::any(glm::lessThan(t.scale, glm::vec3(1e-6f))) ||
      glm::any(glm::greaterThan(t.scale, glm::vec3(1e6f))) ||
      glm::any(glm::greaterThan(glm::abs(t.translate), glm::vec3(float(kMaxCoordinate))))) {
    error = what_node + ": scale outside [1e-6, 1e6] or translation beyond 1e15";
    return false;
  }
  if (residual > 1e-4) {
    warnings.push_back(what_node + ": its transform shears (" + std::to_string(residual) +
                       "); gfield keeps translation, rotation and scale");
  }
  return true;
}

/// The scene.meshes index of glTF mesh `m` (added on first use).
int mesh_asset(const GltfDocument& d, int m, Scene& scene, std::map<int, int>& assets) {
  const auto found = assets.find(m);
  if (found != assets.end())
    return found->second;
  MeshAsset asset;
  asset.file = d.file;
  asset.part = gltf_mesh_part(m);
  asset.asset = gltf_asset_name(d.file, m, d.model.meshes[size_t(m)].name);
  const fs::path stem = fs::path(d.file).parent_path() / asset.asset;
  std::error_code ec;
  if (fs::is_regular_file(stem.string() + ".gimage.exr", ec))
    asset.geometry_image = stem.string() + ".gimage.exr";
  if (fs::is_regular_file(stem.string() + ".gfield.exr", ec))
    asset.geometry_field = stem.string() + ".gfield.exr";
  scene.meshes.push_back(asset);
  assets[m] = int(scene.meshes.size()) - 1;
  return assets[m];
}

bool append_objects(const GltfDocument& d, const std::vector<PlacedNode>& nodes,
                    const glm::dmat4& placement, Scene& scene, std::vector<std::string>& warnings,
                    std::string& error) {
  std::map<int, int> assets;
  for (const PlacedNode& placed : nodes) {
    const tinygltf::Node& node = d.model.nodes[size_t(placed.node)];
    if (node.mesh < 0)
      continue;
    if (scene.objects.size() >= kMaxSceneObjects) {
      error = d.file + ": more than " + std::to_string(kMaxSceneObjects) + " mesh nodes";
      return false;
    }
    const std::string what_node = d.file + ": nodes[" + std::to_string(placed.node) + "]";
    SceneObject o;
    o.name = node.name.empty() ? d.model.meshes[size_t(node.mesh)].name : node.name;
    o.shape.type = ShapeType::kMesh;
    o.shape.mesh = mesh_asset(d, node.mesh, scene, assets);
    const std::vector<tinygltf::Primitive>& primitives =
        d.model.meshes[size_t(node.mesh)].primitives;
    const int material = primitives.empty() ? -1 : primitives[0].material;
    std::string what;
    if (!object_material(d, material, o.material, what)) {
      error = d.file + ": materials[" + std::to_string(material) + "]: " + what;
      return false;
    }
    if (!place(placement * placed.world, what_node, o.transform, warnings, error))
      return false;
    scene.objects.push_back(std::move(o));
  }
  return true;
}

/// The first perspective camera of the scene's nodes; false when there is none.
bool node_camera(const GltfDocument& d, const std::vector<PlacedNode>& nodes, Camera& camera,
                 double& aspect, std::vector<std::string>& warnings) {
  for (const PlacedNode& placed : nodes) {
    const int index = d.model.nodes[size_t(placed.node)].camera;
    if (index < 0)
      continue;
    const tinygltf::Camera& c = d.model.cameras[size_t(index)];
    const double fov = glm::degrees(c.perspective.yfov);
    if (c.type != "perspective" || !(fov > 0.0 && fov < 180.0)) {
      warnings.push_back(d.file + ": cameras[" + std::to_string(index) +
                         "] is not a perspective camera with a field of view in (0, 180) "
                         "degrees; a fitted camera instead");
      return false;
    }
    camera.position = glm::vec3(placed.world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 forward = glm::normalize(glm::dvec3(placed.world * glm::dvec4(0, 0, -1, 0)));
    camera.target = camera.position + glm::vec3(forward);
    camera.up = glm::vec3(glm::normalize(glm::dvec3(placed.world * glm::dvec4(0, 1, 0, 0))));
    camera.fov_degrees = float(fov);
    aspect = c.perspective.aspectRatio > 0.0 ? c.perspective.aspectRatio : 1.0;
    const glm::vec3 view = camera.target - camera.position;
    if (!glm::all(glm::isfinite(camera.position)) || !glm::all(glm::isfinite(camera.up)) ||
        glm::any(glm::greaterThan(glm::abs(camera.position), glm::vec3(1e15f))) ||
        !(glm::length(glm::cross(view, camera.up)) > 1e-6f * glm::length(view))) {
      warnings.push_back(d.file + ": cameras[" + std::to_string(index) +
                         "] is placed by a degenerate transform; a fitted camera instead");
      return false;
    }
    return true;
  }
  return false;
}

/// World bounds of the mesh nodes from their POSITION accessors' min and max.
void scene_bounds(const GltfDocument& d, const std::vector<PlacedNode>& nodes, glm::dvec3& lo,
                  glm::dvec3& hi) {
  lo = glm::dvec3(1e300);
  hi = glm::dvec3(-1e300);
  for (const PlacedNode& placed : nodes) {
    const int m = d.model.nodes[size_t(placed.node)].mesh;
    for (size_t p = 0; m >= 0 && p < d.model.meshes[size_t(m)].primitives.size(); ++p) {
      const auto found = d.model.meshes[size_t(m)].primitives[p].attributes.find("POSITION");
      if (found == d.model.meshes[size_t(m)].primitives[p].attributes.end())
        continue;
      const tinygltf::Accessor& a = d.model.accessors[size_t(found->second)];
      if (a.minValues.size() != 3 || a.maxValues.size() != 3)
        continue;
      for (int c = 0; c < 8; ++c) {
        const glm::dvec3 corner(c & 1 ? a.maxValues[0] : a.minValues[0],
                                c & 2 ? a.maxValues[1] : a.minValues[1],
                                c & 4 ? a.maxValues[2] : a.minValues[2]);
        const glm::dvec3 w(placed.world * glm::dvec4(corner, 1.0));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
      }
    }
  }
  if (lo.x > hi.x) {
    lo = glm::dvec3(-1.0);
    hi = glm::dvec3(1.0);
  }
}

/// A camera looking at the scene's bounds from the front and a little above, fitting them.
Camera fitted_camera(const GltfDocument& d, const std::vector<PlacedNode>& nodes) {
  glm::dvec3 lo, hi;
  scene_bounds(d, nodes, lo, hi);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
  Camera camera;
  camera.fov_degrees = 45.0f;
  const double distance = 1.1 * radius / std::sin(glm::radians(22.5));
  camera.target = glm::vec3(centre);
  camera.position = glm::vec3(centre + distance * glm::normalize(glm::dvec3(0.0, 0.4, 1.0)));
  return camera;
}

/// The KHR_lights_punctual lights of the scene's nodes.
bool node_lights(const GltfDocument& d, const std::vector<PlacedNode>& nodes, Scene& scene,
                 std::vector<std::string>& warnings, std::string& error) {
  for (const PlacedNode& placed : nodes) {
    const json* index = json_at(d.json["nodes"][size_t(placed.node)],
                                {"extensions", "KHR_lights_punctual", "light"});
    if (index == nullptr)
      continue;
    const json& l = d.json["extensions"]["KHR_lights_punctual"]["lights"][index->get<size_t>()];
    Light light;
    const std::string type = l.value("type", "");
    light.type = type == "directional" ? LightType::kDirectional : LightType::kPoint;
    if (type != "directional" && type != "point")
      warnings.push_back(d.file + ": light " + index->dump() + " of type '" + type +
                         "' becomes a point light");
    double intensity = 1.0, c[3] = {1.0, 1.0, 1.0};
    std::string what;
    bool ok = number_at(l, {"intensity"}, 1.0, 0.0, kMaxColorComponent, intensity, what);
    for (size_t k = 0; k < 3 && ok && l.contains("color") && l["color"].is_array(); ++k) {
      ok = l["color"].size() > k && l["color"][k].is_number();
      c[k] = ok ? l["color"][k].get<double>() : 0.0;
      ok = ok && c[k] >= 0.0 && c[k] <= kMaxColorComponent;
    }
    light.position = glm::vec3(placed.world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    light.direction = glm::vec3(glm::normalize(glm::dvec3(placed.world * glm::dvec4(0, 0, -1, 0))));
    if (!ok || glm::any(glm::greaterThan(glm::abs(light.position), glm::vec3(1e15f)))) {
      error = d.file + ": light " + index->dump() +
              ": colour or intensity outside [0, 1e6], or "
              "a position beyond 1e15";
      return false;
    }
    light.intensity = float(intensity);
    light.color = glm::vec3(float(c[0]), float(c[1]), float(c[2]));
    scene.lights.push_back(light);
  }
  return scene.lights.size() <= kMaxSceneLights ||
         (error = d.file + ": more than " + std::to_string(kMaxSceneLights) + " lights", false);
}

/// The scene settings of the file's extras "gfield" object (the scene's, else the asset's):
/// purpose, image, environment, ambient, read as a JSON scene reads them. `has_image` and
/// `has_ambient` tell which were given.
bool gltf_scene_settings(const GltfDocument& d, Scene& scene, bool& has_image, bool& has_ambient,
                         std::string& error) {
  const int index = d.model.defaultScene >= 0 ? d.model.defaultScene : 0;
  const json* extras = d.json.contains("scenes") && size_t(index) < d.json["scenes"].size()
                           ? json_at(d.json["scenes"][size_t(index)], {"extras", "gfield"})
                           : nullptr;
  extras = extras != nullptr ? extras : json_at(d.json, {"asset", "extras", "gfield"});
  json text = {{"camera", {{"position", {0, 0, 1}}, {"target", {0, 0, 0}}}}};
  has_image = has_ambient = false;
  if (extras != nullptr && !extras->is_object()) {
    error = d.file + ": extras.gfield: expected an object";
    return false;
  }
  static const json kNone = json::object();
  for (const auto& [key, value] : (extras != nullptr ? *extras : kNone).items()) {
    if (key != "purpose" && key != "image" && key != "environment" && key != "ambient") {
      error = d.file + ": extras.gfield." + key +
              ": unknown key (expected purpose, image, environment or ambient)";
      return false;
    }
    text[key] = value;
    has_image = has_image || key == "image";
    has_ambient = has_ambient || key == "ambient";
  }
  if (!parse_scene(text.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                   d.file + " (extras.gfield)", scene, error))
    return false;
  scene.filename = d.file;
  if (scene.purpose.empty())
    scene.purpose = "glTF scene " + fs::path(d.file).filename().string();
  return true;
}

}  // namespace

std::string gltf_asset_name(const std::string& filename, int index, const std::string& name) {
  std::string clean;
  for (const char c : name) {
    if (clean.size() < 40)
      clean += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  }
  return fs::path(filename).stem().string() + "." + std::to_string(index) +
         (clean.empty() ? "" : "-" + clean);
}

bool append_gltf_objects(const std::string& filename, const glm::dmat4& placement, Scene& scene,
                         std::vector<std::string>& warnings, std::string& error) {
  GltfDocument d;
  std::vector<PlacedNode> nodes;
  return load_gltf_document(filename, d, error) && scene_nodes(d, nodes, error) &&
         append_objects(d, nodes, placement, scene, warnings, error);
}

bool load_gltf_scene(const std::string& filename, Scene& scene, std::vector<std::string>& warnings,
                     std::string& error) {
  GltfDocument d;
  std::vector<PlacedNode> nodes;
  if (!load_gltf_document(filename, d, error) || !scene_nodes(d, nodes, error))
    return false;
  Scene result;
  bool has_image = false, has_ambient = false;
  if (!gltf_scene_settings(d, result, has_image, has_ambient, error))
    return false;
  double aspect = 1.0;
  if (!node_camera(d, nodes, result.camera, aspect, warnings))
    result.camera = fitted_camera(d, nodes);
  else if (!has_image)
    result.height = std::clamp(int(std::lround(result.width / aspect)), 1, 16384);
  if (!append_objects(d, nodes, glm::dmat4(1.0), result, warnings, error) ||
      !node_lights(d, nodes, result, warnings, error))
    return false;
  if (!has_ambient)
    result.ambient = glm::vec3(result.lights.empty() ? 1.0f : 0.1f);
  scene = std::move(result);
  return true;
}

}  // namespace gfield
