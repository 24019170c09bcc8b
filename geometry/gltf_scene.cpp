#include "geometry/gltf_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include <glm/gtx/compatibility.hpp>

#include "geometry/gltf_document.hpp"
#include "geometry/gltf_extensions.hpp"
#include "geometry/gltf_material.hpp"
#include "geometry/gltf_mesh.hpp"
#include "gfield/limits.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// A node's world matrix (after `placement`) as a Transform; a shear is dropped with a warning.
bool place(const glm::dmat4& world, const std::string& what_node, Transform& t,
           std::vector<std::string>& warnings, std::string& error) {
  double residual = 0.0;
  if (!transform_from_matrix(world, t, residual)) {
    error = what_node + ": a mirroring or singular transform (gfield needs positive scales)";
    return false;
  }
  if (glm::any(glm::lessThan(t.scale, glm::vec3(float(kMinScaleFactor)))) ||
      glm::any(glm::greaterThan(t.scale, glm::vec3(float(kMaxScaleFactor)))) ||
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
  asset.outside_paths = d.outside_paths;
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

/// "diffuse", "mirror", "dielectric".
const char* kind_name(MaterialType type) {
  return type == MaterialType::kMirror       ? "mirror"
         : type == MaterialType::kDielectric ? "dielectric"
                                             : "diffuse";
}

/// |signed volume| / area^1.5 of glTF mesh `mesh` in its own coordinates, the volume taken about
/// the surface's area-weighted centroid: 0 for a flat surface whatever its boundary, about 0.09
/// for a sphere. False with `error` when the mesh does not read.
bool volume_ratio(const GltfDocument& d, int mesh, double& ratio, std::string& error) {
  TriangleMesh m;
  std::vector<std::string> ignored;  // its bounds were checked by mesh_bounds
  if (!read_gltf_mesh(d, gltf_mesh_part(mesh), m, nullptr, false, ignored, error))
    return false;
  glm::dvec3 centroid(0.0);
  double area = 0.0, volume = 0.0;
  for (const glm::ivec3& t : m.triangles) {
    const glm::dvec3 &a = m.positions[size_t(t.x)], &b = m.positions[size_t(t.y)],
                     &c = m.positions[size_t(t.z)];
    const double A = 0.5 * glm::length(glm::cross(b - a, c - a));
    area += A;
    centroid += A * (a + b + c) / 3.0;
  }
  centroid /= std::max(area, 1e-300);
  for (const glm::ivec3& t : m.triangles)
    volume += glm::dot(m.positions[size_t(t.x)] - centroid,
                       glm::cross(m.positions[size_t(t.y)] - centroid,
                                  m.positions[size_t(t.z)] - centroid)) /
              6.0;
  ratio = std::abs(volume) / std::max(std::pow(area, 1.5), 1e-300);
  return true;
}

/// The materials of the document as gfield materials, each mapped (and warned about) once.
struct MaterialCache {
  std::map<int, Material> mapped;
};

/// The material of glTF material `index` (cached); false with `error`.
bool cached_material(const GltfDocument& d, int index, MaterialCache& cache, Material& m,
                     std::vector<std::string>& warnings, std::string& error) {
  const auto found = cache.mapped.find(index);
  if (found != cache.mapped.end()) {
    m = found->second;
    return true;
  }
  if (!gltf_object_material(d, index, m, warnings, error))
    return false;
  cache.mapped[index] = m;
  return true;
}

/// The material of glTF mesh `mesh` (its first primitive's); a warning when its other primitives'
/// materials map to another kind; a dielectric mesh whose surface encloses no volume refused.
bool mesh_material(const GltfDocument& d, int mesh, MaterialCache& cache, Material& m,
                   std::vector<std::string>& warnings, std::string& error) {
  const std::vector<tinygltf::Primitive>& primitives = d.model.meshes[size_t(mesh)].primitives;
  if (!cached_material(d, primitives.empty() ? -1 : primitives[0].material, cache, m, warnings,
                       error))
    return false;
  const std::string place = d.file + ": meshes[" + std::to_string(mesh) + "]";
  for (size_t p = 1; p < primitives.size(); ++p) {
    Material other;
    if (!cached_material(d, primitives[p].material, cache, other, warnings, error))
      return false;
    if (other.type != m.type) {
      warnings.push_back(place + ": primitives[" + std::to_string(p) + "]'s material is " +
                         kind_name(other.type) + ", the first primitive's " + kind_name(m.type) +
                         "; gfield renders the whole mesh as the first");
      break;
    }
  }
  double ratio = 1.0;
  if (m.type == MaterialType::kDielectric && !volume_ratio(d, mesh, ratio, error))
    return false;
  if (ratio >= 1e-6)
    return true;
  error = place +
          ": a transmissive surface that encloses no volume (flat and open); gfield's "
          "dielectrics are closed solids (a JSON scene refuses a dielectric quad likewise)";
  return false;
}

bool append_objects(const GltfDocument& d, const std::vector<PlacedNode>& nodes,
                    const glm::dmat4& placement, Scene& scene, std::vector<std::string>& warnings,
                    std::string& error) {
  std::map<int, int> assets;
  MaterialCache cache;
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
    if (!mesh_material(d, node.mesh, cache, o.material, warnings, error) ||
        !place(placement * placed.world, what_node, o.transform, warnings, error))
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

/// A box: lo > hi when empty.
using Bounds = std::pair<glm::dvec3, glm::dvec3>;

/// The bounds of every glTF mesh the nodes place, in its own coordinates, computed from its
/// primitives' POSITION data (the accessors' declared min and max are not trusted: those that
/// the data contradict are warnings).
std::map<int, Bounds> mesh_bounds(const GltfDocument& d, const std::vector<PlacedNode>& nodes,
                                  std::vector<std::string>& warnings) {
  std::map<int, Bounds> bounds;
  std::map<int, Bounds> accessors;
  for (const PlacedNode& placed : nodes) {
    const int m = d.model.nodes[size_t(placed.node)].mesh;
    if (m < 0 || bounds.count(m))
      continue;
    Bounds& box = bounds[m] = {glm::dvec3(std::numeric_limits<double>::max()),
                               glm::dvec3(-std::numeric_limits<double>::max())};
    for (const tinygltf::Primitive& p : d.model.meshes[size_t(m)].primitives) {
      const auto found = p.attributes.find("POSITION");
      if (found == p.attributes.end())
        continue;
      if (!accessors.count(found->second)) {
        Bounds& a = accessors[found->second];
        position_bounds(read_accessor_floats(d, found->second), a.first, a.second);
        check_declared_bounds(d, found->second, a.first, a.second, warnings);
      }
      box.first = glm::min(box.first, accessors[found->second].first);
      box.second = glm::max(box.second, accessors[found->second].second);
    }
  }
  return bounds;
}

/// World bounds of the mesh nodes (their meshes' `bounds` placed by the nodes); [-1, 1]^3 when
/// there are none.
Bounds scene_bounds(const GltfDocument& d, const std::vector<PlacedNode>& nodes,
                    const std::map<int, Bounds>& bounds) {
  Bounds world = {glm::dvec3(1e300), glm::dvec3(-1e300)};
  for (const PlacedNode& placed : nodes) {
    const auto found = bounds.find(d.model.nodes[size_t(placed.node)].mesh);
    if (found == bounds.end() || found->second.first.x > found->second.second.x)
      continue;
    const auto& [lo, hi] = found->second;
    for (int c = 0; c < 8; ++c) {
      const glm::dvec3 corner(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
      const glm::dvec3 w(placed.world * glm::dvec4(corner, 1.0));
      world.first = glm::min(world.first, w);
      world.second = glm::max(world.second, w);
    }
  }
  if (world.first.x > world.second.x)
    world = {glm::dvec3(-1.0), glm::dvec3(1.0)};
  return world;
}

/// A camera looking at the world bounds [lo, hi] from the front and a little above, fitting them.
Camera fitted_camera(const Bounds& bounds) {
  const auto& [lo, hi] = bounds;
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
  Camera camera;
  camera.fov_degrees = 45.0f;
  const double distance = 1.1 * radius / std::sin(glm::radians(22.5));
  camera.target = glm::vec3(centre);
  camera.position = glm::vec3(centre + distance * glm::normalize(glm::dvec3(0.0, 0.4, 1.0)));
  return camera;
}

/// A KHR_lights_punctual light's intensity and colour, each in [0, 1e6] as in JSON scenes.
bool light_values(const json& l, Light& light, std::string& what) {
  double intensity = 1.0;
  if (!number_at(l, {"intensity"}, 1.0, 0.0, kMaxColorComponent, "[0, 1e6]", intensity, what))
    return false;
  light.intensity = float(intensity);
  const json* color = json_at(l, {"color"});
  if (color == nullptr)
    return true;
  glm::dvec3 c(-1.0);
  for (size_t k = 0; k < 3 && color->is_array() && color->size() == 3; ++k)
    c[int(k)] = (*color)[k].is_number() ? (*color)[k].get<double>() : -1.0;
  if (glm::any(glm::lessThan(c, glm::dvec3(0.0))) ||
      glm::any(glm::greaterThan(c, glm::dvec3(kMaxColorComponent)))) {
    what = "color must be 3 numbers in [0, 1e6] (is " +
           color->dump(-1, ' ', false, json::error_handler_t::replace) + ")";
    return false;
  }
  light.color = glm::vec3(c);
  return true;
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
    std::string what;
    const glm::dvec3 position(placed.world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    light.position = glm::vec3(position);
    light.direction = glm::vec3(glm::normalize(glm::dvec3(placed.world * glm::dvec4(0, 0, -1, 0))));
    if (glm::any(glm::greaterThan(glm::abs(position), glm::dvec3(kMaxCoordinate))))
      what = "nodes[" + std::to_string(placed.node) + "] places it beyond 1e15";
    if (!what.empty() || !light_values(l, light, what)) {
      error = d.file + ": extensions.KHR_lights_punctual.lights[" + index->dump() + "]: " + what;
      return false;
    }
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
                   d.file + " (extras.gfield)", scene, error, d.outside_paths))
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

bool append_gltf_objects(const std::string& filename, OutsidePaths outside,
                         const glm::dmat4& placement, Scene& scene,
                         std::vector<std::string>& warnings, std::string& error) {
  GltfDocument d;
  std::vector<PlacedNode> nodes;
  if (!load_gltf_document(filename, outside, d, error) || !scene_nodes(d, nodes, error))
    return false;
  ignored_extension_warnings(d.file, d.json, warnings);
  mesh_bounds(d, nodes, warnings);  // for its warnings: gfield reads the bounds of the data
  return append_objects(d, nodes, placement, scene, warnings, error);
}

bool load_gltf_scene(const std::string& filename, OutsidePaths outside, Scene& scene,
                     std::vector<std::string>& warnings, std::string& error) {
  GltfDocument d;
  std::vector<PlacedNode> nodes;
  if (!load_gltf_document(filename, outside, d, error) || !scene_nodes(d, nodes, error))
    return false;
  ignored_extension_warnings(d.file, d.json, warnings);
  const std::map<int, Bounds> bounds = mesh_bounds(d, nodes, warnings);
  Scene result;
  bool has_image = false, has_ambient = false;
  if (!gltf_scene_settings(d, result, has_image, has_ambient, error))
    return false;
  double aspect = 1.0;
  if (!node_camera(d, nodes, result.camera, aspect, warnings))
    result.camera = fitted_camera(scene_bounds(d, nodes, bounds));
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
