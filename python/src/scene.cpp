// gfield.load_scene: a scene file (JSON or glTF, docs/scenes.md) as a dict, read as `gfield
// render` and gfield-view read it.

#include <nlohmann/json.hpp>

#include "geometry/scene_file.hpp"
#include "gfield/printable.hpp"
#include "python/src/bindings.hpp"
#include "python/src/json_object.hpp"

namespace gfield::python {
namespace {

// The name tables below are indexed by the contract's codes (shaders/lib/contract.glsl).
static_assert(int(EnvironmentType::kStudio) == 0 && int(EnvironmentType::kCube) == 3);
static_assert(int(MaterialType::kDiffuse) == 0 && int(MaterialType::kDielectric) == 2);
static_assert(int(TextureType::kNone) == 0 && int(TextureType::kMesh) == 3);

nlohmann::json vec(glm::vec3 v) {
  return {v.x, v.y, v.z};
}

nlohmann::json camera_json(const Camera& c) {
  return {{"position", vec(c.position)},
          {"target", vec(c.target)},
          {"up", vec(c.up)},
          {"fov_degrees", c.fov_degrees}};
}

nlohmann::json environment_json(const EnvironmentDesc& e) {
  const char* types[] = {"studio", "constant", "equirect", "cube"};
  nlohmann::json j = {{"type", types[int(e.type)]}, {"intensity", e.intensity}};
  if (e.type == EnvironmentType::kConstant) {
    j["color"] = vec(e.color);
  } else if (e.type == EnvironmentType::kEquirect) {
    j["file"] = printable(e.file);
  } else if (e.type == EnvironmentType::kCube) {
    j["faces"] = nlohmann::json::array();
    for (const std::string& face : e.faces) {
      j["faces"].push_back(printable(face));
    }
  }
  return j;
}

nlohmann::json light_json(const Light& l) {
  nlohmann::json j = {{"color", vec(l.color)}, {"intensity", l.intensity}};
  if (l.type == LightType::kDirectional) {
    j["type"] = "directional";
    j["direction"] = vec(l.direction);
  } else {
    j["type"] = "point";
    j["position"] = vec(l.position);
  }
  return j;
}

nlohmann::json material_json(const Material& m) {
  const char* types[] = {"diffuse", "mirror", "dielectric"};
  const char* textures[] = {"none", "checker", "color-chart", "mesh"};
  nlohmann::json j = {{"type", types[int(m.type)]}, {"color", vec(m.color)}};
  if (m.type == MaterialType::kDiffuse) {
    j["texture"] = textures[int(m.texture)];
    if (m.texture == TextureType::kChecker) {
      j["colors"] = {vec(m.checker_colors[0]), vec(m.checker_colors[1])};
      j["scale"] = {m.checker_scale.x, m.checker_scale.y};
    }
  } else if (m.type == MaterialType::kDielectric) {
    j["ior"] = m.ior;
    j["absorption"] = vec(m.absorption);
    if (!m.ior_preset.empty()) {
      j["ior_preset"] = m.ior_preset;
    }
  }
  return j;
}

nlohmann::json object_json(const SceneObject& o) {
  const Shape& s = o.shape;
  nlohmann::json shape = {{"type", shape_name(s.type)}};
  switch (s.type) {
    case ShapeType::kMesh:
      shape["mesh"] = s.mesh;
      shape["smooth_normals"] = s.smooth_normals;
      break;
    case ShapeType::kSphere:
      shape["radius"] = s.radius;
      break;
    case ShapeType::kCylinder:
      shape["radius"] = s.radius;
      shape["height"] = s.height;
      break;
    case ShapeType::kHollowCylinder:
      shape["radius"] = s.radius;
      shape["height"] = s.height;
      shape["thickness"] = s.thickness;
      break;
    case ShapeType::kSlab:
      shape["size"] = {s.size.x, s.size.y};
      shape["thickness"] = s.thickness;
      break;
    case ShapeType::kQuad:
      shape["size"] = {s.size.x, s.size.y};
      break;
    case ShapeType::kBox:
      shape["size"] = vec(s.size);
      break;
  }
  return {{"name", printable(o.name)},
          {"shape", shape},
          {"transform",
           {{"translate", vec(o.transform.translate)},
            {"rotate_degrees", vec(o.transform.rotate_degrees)},
            {"scale", vec(o.transform.scale)}}},
          {"material", material_json(o.material)}};
}

nlohmann::json scene_json(const Scene& scene) {
  nlohmann::json j = {{"file", printable(scene.filename)},
                      {"purpose", printable(scene.purpose)},
                      {"camera", camera_json(scene.camera)},
                      {"width", scene.width},
                      {"height", scene.height},
                      {"environment", environment_json(scene.environment)},
                      {"ambient", vec(scene.ambient)},
                      {"lights", nlohmann::json::array()},
                      {"meshes", nlohmann::json::array()},
                      {"objects", nlohmann::json::array()}};
  for (const Light& light : scene.lights) {
    j["lights"].push_back(light_json(light));
  }
  for (const MeshAsset& mesh : scene.meshes) {
    j["meshes"].push_back({{"file", printable(mesh.file)},
                           {"part", printable(mesh.part)},
                           {"asset", printable(mesh.asset)},
                           {"geometry_image", printable(mesh.geometry_image)},
                           {"geometry_field", printable(mesh.geometry_field)}});
  }
  for (const SceneObject& object : scene.objects) {
    j["objects"].push_back(object_json(object));
  }
  return j;
}

py::object load(const std::filesystem::path& path, bool allow_outside_paths) {
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  bool loaded = false;
  {
    py::gil_scoped_release release;
    loaded = load_scene_file(path_text(path), scene, warnings, error,
                             allow_outside_paths ? OutsidePaths::kAllowed : OutsidePaths::kRefused);
  }
  if (!loaded) {
    throw Error(error);
  }
  warn(warnings);
  return json_to_python(scene_json(scene));
}

}  // namespace

void bind_scene(py::module_& m) {
  m.def("load_scene", &load, py::arg("path"), py::kw_only(), py::arg("allow_outside_paths") = false,
        "Reads a scene (.json, docs/scenes.md, or a glTF file .gltf/.glb) as gfield render and\n"
        "gfield-view read it (glTF objects expanded, meshes' own colours resolved) and returns\n"
        "it as a dict: file, purpose, camera {position, target, up, fov_degrees}, width,\n"
        "height, environment {type, intensity, ...}, ambient, lights [{type, color, intensity,\n"
        "direction | position}], meshes [{file, part, asset, geometry_image, geometry_field}]\n"
        "and objects [{name, shape {type, ...; mesh: index into meshes}, transform {translate,\n"
        "rotate_degrees, scale}, material {type, color, ...}}]; vectors as lists, paths\n"
        "resolved. Raises gfield.Error with the one-line message (FILE:LINE:COLUMN: key:\n"
        "problem).");
}

}  // namespace gfield::python
