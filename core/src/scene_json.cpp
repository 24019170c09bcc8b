// Scene files (docs/scenes.md): the JSON document read and validated into a Scene, every
// failure "FILE:LINE:COL: path: problem" (scene_reader.hpp reads the values).

#include "gfield/scene.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "gfield/camera_text.hpp"
#include "gfield/file_read.hpp"
#include "gfield/limits.hpp"
#include "gfield/located_json.hpp"
#include "gfield/optics.hpp"
#include "gfield/printable.hpp"
#include "scene_reader.hpp"

namespace gfield {
namespace fs = std::filesystem;
namespace {

using nlohmann::json;

Camera read_camera(const SceneReader& r, const std::string& p) {
  r.object(p, {"position", "target", "up", "fov"});
  r.require(p, "position");
  r.require(p, "target");
  Camera c;
  c.position = r.vec3(p, "position", c.position);
  c.target = r.vec3(p, "target", c.target);
  c.up = r.vec3(p, "up", c.up);
  c.fov_degrees = float(r.number(p, "fov", c.fov_degrees));
  std::string key;
  if (const std::string problem = camera_problem(c, &key); !problem.empty())
    throw JsonFailure{key.empty() ? p : json_pointer_child(p, key), problem};
  return c;
}

EnvironmentDesc read_environment(const SceneReader& r, const std::string& p) {
  r.object(p, {"type", "color", "intensity", "file", "faces"});
  EnvironmentDesc e;
  const std::string type = r.string(p, "type", "studio");
  e.intensity = float(r.intensity(p));
  auto forbid = [&](const char* key) {
    if (r.has(p, key)) {
      throw JsonFailure{
          json_pointer_child(p, key),
          std::string("\"") + key + "\" does not apply to a \"" + type + "\" environment"};
    }
  };
  if (type == "studio") {
    e.type = EnvironmentType::kStudio;
    forbid("color");
    forbid("file");
    forbid("faces");
  } else if (type == "constant") {
    e.type = EnvironmentType::kConstant;
    r.require(p, "color");
    e.color = r.color(p, "color", e.color);
    forbid("file");
    forbid("faces");
  } else if (type == "equirect") {
    e.type = EnvironmentType::kEquirect;
    r.require(p, "file");
    e.file = r.file(json_pointer_child(p, "file"));
    forbid("color");
    forbid("faces");
  } else if (type == "cube") {
    e.type = EnvironmentType::kCube;
    r.require(p, "faces");
    const std::string fp = json_pointer_child(p, "faces");
    if (!r.at(fp).is_array() || r.at(fp).size() != 6) {
      throw JsonFailure{fp, "expected 6 files in the order +X, -X, +Y, -Y, +Z, -Z"};
    }
    for (size_t f = 0; f < 6; ++f)
      e.faces[f] = r.file(json_pointer_child(fp, f));
    forbid("color");
    forbid("file");
  } else {
    throw JsonFailure{json_pointer_child(p, "type"),
                      "unknown environment type \"" + type + "\" (expected " +
                          list_names({"studio", "constant", "equirect", "cube"}) + ")"};
  }
  return e;
}

Light read_light(const SceneReader& r, const std::string& p) {
  r.object(p, {"type", "direction", "position", "color", "intensity"});
  r.require(p, "type");
  Light l;
  const std::string type = r.string(json_pointer_child(p, "type"));
  l.color = r.color(p, "color", l.color);
  l.intensity = float(r.intensity(p));
  if (type == "directional") {
    l.type = LightType::kDirectional;
    r.require(p, "direction");
    if (r.has(p, "position")) {
      throw JsonFailure{json_pointer_child(p, "position"), "a directional light has no position"};
    }
    const glm::vec3 d = r.vec3(json_pointer_child(p, "direction"));
    if (glm::length(d) <= 0.0f)
      throw JsonFailure{json_pointer_child(p, "direction"), "zero direction"};
    l.direction = glm::normalize(d);
  } else if (type == "point") {
    l.type = LightType::kPoint;
    r.require(p, "position");
    if (r.has(p, "direction")) {
      throw JsonFailure{json_pointer_child(p, "direction"), "a point light has no direction"};
    }
    l.position = r.vec3(json_pointer_child(p, "position"));
  } else {
    throw JsonFailure{json_pointer_child(p, "type"),
                      "unknown light type \"" + type + "\" (expected directional or point)"};
  }
  return l;
}

/// The "texture" of a diffuse material: none, checker or color-chart on analytic shapes; mesh or
/// none on meshes (default: none; the mesh's own base colour is chosen once the mesh is read).
TextureType read_texture(const SceneReader& r, const std::string& p, ShapeType shape) {
  const std::string texture = r.string(p, "texture", "none");
  const std::string tp = json_pointer_child(p, "texture");
  const bool mesh = shape == ShapeType::kMesh;
  if (texture == "none") {
    return TextureType::kNone;
  }
  if (texture == "mesh" && mesh) {
    return TextureType::kMesh;
  }
  if (!mesh && texture == "checker") {
    return TextureType::kChecker;
  }
  if (!mesh && texture == "color-chart") {
    return TextureType::kColorChart;
  }
  if (texture == "mesh" || texture == "checker" || texture == "color-chart") {
    throw JsonFailure{tp, mesh ? "a mesh takes \"mesh\" (its own texture, vertex or material "
                                 "colours) or \"none\"; procedural textures apply to analytic "
                                 "shapes"
                               : "\"mesh\" applies to meshes (analytic shapes take none, "
                                 "checker or color-chart)"};
  }
  throw JsonFailure{tp, "unknown texture \"" + texture + "\" (expected " +
                            (mesh ? "mesh or none" : "none, checker or color-chart") + ")"};
}

/// A checker texture's "colors" (two colours) and "scale" (squares along u and v: a number or
/// two, positive) into `m`.
void read_checker(const SceneReader& r, const std::string& p, Material& m) {
  if (r.has(p, "colors")) {
    const std::string cp = json_pointer_child(p, "colors");
    if (!r.at(cp).is_array() || r.at(cp).size() != 2) {
      throw JsonFailure{cp, "expected two colours"};
    }
    for (size_t i = 0; i < 2; ++i) {
      m.checker_colors[i] = r.color(json_pointer_child(cp, i));
    }
  }
  if (r.has(p, "scale")) {
    const std::string sp = json_pointer_child(p, "scale");
    if (r.at(sp).is_number()) {
      m.checker_scale = glm::vec2(float(r.number(sp)));
    } else if (r.at(sp).is_array() && r.at(sp).size() == 2) {
      m.checker_scale = glm::vec2(float(r.number(json_pointer_child(sp, size_t(0)))),
                                  float(r.number(json_pointer_child(sp, size_t(1)))));
    } else {
      throw JsonFailure{sp, "expected a number or [squares along u, squares along v]"};
    }
    if (!(m.checker_scale.x > 0.0f && m.checker_scale.y > 0.0f)) {
      throw JsonFailure{sp, "must be positive"};
    }
  }
}

/// A dielectric's "ior": a number in [kMinIor, kMaxIor] or a preset's name (optics.hpp).
void read_ior(const SceneReader& r, const std::string& p, Material& m) {
  r.require(p, "ior");
  const std::string ip = json_pointer_child(p, "ior");
  if (r.at(ip).is_string()) {
    m.ior_preset = r.string(ip);
    const auto index = find_ior_preset(m.ior_preset);
    if (!index) {
      std::string names;
      for (const IorPreset& preset : ior_presets()) {
        names += (names.empty() ? "" : ", ") + std::string(preset.name);
      }
      throw JsonFailure{
          ip, "unknown refractive index preset \"" + m.ior_preset + "\" (known: " + names + ")"};
    }
    m.ior = *index;
  } else {
    m.ior = float(r.in_range(ip, kMinIor, kMaxIor, "[1e-6, 1e6]", "an index of refraction"));
  }
}

Material read_material(const SceneReader& r, const std::string& p, ShapeType shape) {
  r.object(p, {"type", "color", "texture", "colors", "scale", "tint", "ior", "absorption"});
  r.require(p, "type");
  Material m;
  const std::string type = r.string(json_pointer_child(p, "type"));
  auto only = [&](std::initializer_list<const char*> allowed) {
    for (const char* key : {"color", "texture", "colors", "scale", "tint", "ior", "absorption"}) {
      const bool ok = std::any_of(allowed.begin(), allowed.end(),
                                  [&](const char* a) { return std::string(a) == key; });
      if (!ok && r.has(p, key)) {
        throw JsonFailure{json_pointer_child(p, key),
                          std::string("\"") + key + "\" does not apply to a " + type + " material"};
      }
    }
  };
  if (type == "diffuse") {
    m.type = MaterialType::kDiffuse;
    only({"color", "texture", "colors", "scale"});
    m.color = r.color(p, "color", m.color);
    m.texture = read_texture(r, p, shape);
    m.texture_by_mesh = shape == ShapeType::kMesh && !r.has(p, "texture");
    m.default_color = !r.has(p, "color");
    if (m.texture != TextureType::kChecker) {
      for (const char* key : {"colors", "scale"}) {
        if (r.has(p, key)) {
          throw JsonFailure{json_pointer_child(p, key),
                            std::string("\"") + key + "\" applies to the checker texture only"};
        }
      }
    }
    read_checker(r, p, m);
  } else if (type == "mirror") {
    m.type = MaterialType::kMirror;
    only({"tint"});
    m.color = r.color(p, "tint", glm::vec3(1.0f));
  } else if (type == "dielectric") {
    m.type = MaterialType::kDielectric;
    only({"ior", "absorption"});
    if (!shape_is_closed(shape)) {
      throw JsonFailure{p, std::string("a dielectric needs a closed shape (a ") +
                               shape_name(shape) + " bounds no volume)"};
    }
    read_ior(r, p, m);
    m.absorption = r.color(p, "absorption", m.absorption);
  } else {
    throw JsonFailure{
        json_pointer_child(p, "type"),
        "unknown material type \"" + type + "\" (expected diffuse, mirror or dielectric)"};
  }
  return m;
}

Transform read_transform(const SceneReader& r, const std::string& p) {
  r.object(p, {"translate", "rotate", "scale"});
  Transform t;
  t.translate = r.vec3(p, "translate", t.translate);
  t.rotate_degrees = r.vec3(p, "rotate", t.rotate_degrees);
  if (r.has(p, "scale")) {
    t.scale =
        glm::vec3(r.vec3_in_range(json_pointer_child(p, "scale"), kMinScaleFactor, kMaxScaleFactor,
                                  "[1e-6, 1e6]", "scale factors (no mirroring, no flattening)"));
  }
  return t;
}

/// NAME.<kind>.exr beside the mesh file if it exists, else "".
std::string beside(const fs::path& mesh, const char* kind) {
  const fs::path candidate = mesh.parent_path() / (mesh.stem().string() + "." + kind + ".exr");
  return file_problem(candidate.string()) == "no such file" ? std::string() : candidate.string();
}

/// The shape type at p/shape (gltf objects are includes, read before).
ShapeType read_shape_type(const SceneReader& r, const std::string& p) {
  const std::string shape = r.string(json_pointer_child(p, "shape"));
  const std::pair<const char*, ShapeType> shapes[] = {
      {"mesh", ShapeType::kMesh},
      {"sphere", ShapeType::kSphere},
      {"quad", ShapeType::kQuad},
      {"box", ShapeType::kBox},
      {"cylinder", ShapeType::kCylinder},
      {"slab", ShapeType::kSlab},
      {"hollow-cylinder", ShapeType::kHollowCylinder}};
  const auto found = std::find_if(std::begin(shapes), std::end(shapes),
                                  [&](const auto& s) { return shape == s.first; });
  if (found == std::end(shapes)) {
    throw JsonFailure{json_pointer_child(p, "shape"),
                      "unknown shape \"" + shape + "\" (expected " +
                          list_names({"mesh", "sphere", "quad", "box", "cylinder", "slab",
                                      "hollow-cylinder", "gltf"}) +
                          ")"};
  }
  return found->second;
}

/// Refuses the keys of the object at p that do not apply to its shape `type`.
void check_shape_keys(const SceneReader& r, const std::string& p, ShapeType type) {
  std::set<std::string> allowed = {"name", "shape", "transform", "material"};
  switch (type) {
    case ShapeType::kMesh:
      allowed.insert({"file", "gimage", "gfield", "normals"});
      break;
    case ShapeType::kSphere:
      allowed.insert("radius");
      break;
    case ShapeType::kQuad:
      allowed.insert("size");
      break;
    case ShapeType::kBox:
      allowed.insert("size");
      break;
    case ShapeType::kCylinder:
      allowed.insert({"radius", "height"});
      break;
    case ShapeType::kSlab:
      allowed.insert({"size", "thickness"});
      break;
    case ShapeType::kHollowCylinder:
      allowed.insert({"radius", "height", "thickness"});
      break;
  }
  for (auto it = r.at(p).begin(); it != r.at(p).end(); ++it) {
    if (!allowed.count(it.key())) {
      throw JsonFailure{json_pointer_child(p, it.key()),
                        "\"" + it.key() + "\" does not apply to a " + shape_name(type)};
    }
  }
}

/// A quad's or a slab's [width, height] at p/size (positive), or `fallback`.
glm::vec3 read_size2(const SceneReader& r, const std::string& p, glm::vec3 fallback) {
  if (!r.has(p, "size"))
    return fallback;
  const std::string sp = json_pointer_child(p, "size");
  const json& v = r.at(sp);
  if (!v.is_array() || v.size() != 2)
    throw JsonFailure{sp, "expected [width, height]"};
  glm::vec3 out(float(r.number(json_pointer_child(sp, size_t(0)))),
                float(r.number(json_pointer_child(sp, size_t(1)))), 0.0f);
  if (!(out.x > 0.0f && out.y > 0.0f))
    throw JsonFailure{sp, "sizes must be positive"};
  return out;
}

/// A mesh object's file, assets and normals into `s`: instances of one mesh file share its
/// MeshAsset in scene.meshes.
void read_mesh_shape(const SceneReader& r, const std::string& p, Scene& scene, Shape& s) {
  r.require(p, "file");
  const fs::path file = r.file(json_pointer_child(p, "file"));
  MeshAsset asset;
  asset.file = file.string();
  asset.outside_paths = r.outside();
  asset.asset = file.stem().string();
  asset.geometry_image =
      r.has(p, "gimage") ? r.file(json_pointer_child(p, "gimage")) : beside(file, "gimage");
  asset.geometry_field =
      r.has(p, "gfield") ? r.file(json_pointer_child(p, "gfield")) : beside(file, "gfield");
  const std::string normals = r.string(p, "normals", "smooth");
  if (normals != "smooth" && normals != "flat") {
    throw JsonFailure{json_pointer_child(p, "normals"), "expected \"smooth\" or \"flat\""};
  }
  s.smooth_normals = normals == "smooth";
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file, ec);
  auto same = std::find_if(scene.meshes.begin(), scene.meshes.end(), [&](const MeshAsset& m) {
    std::error_code e2;
    return fs::weakly_canonical(m.file, e2) == canonical;
  });
  if (same == scene.meshes.end()) {
    scene.meshes.push_back(asset);
    s.mesh = int(scene.meshes.size()) - 1;
    return;
  }
  if ((r.has(p, "gimage") && same->geometry_image != asset.geometry_image) ||
      (r.has(p, "gfield") && same->geometry_field != asset.geometry_field)) {
    throw JsonFailure{p, "instances of one mesh file must name the same gimage/gfield"};
  }
  s.mesh = int(same - scene.meshes.begin());
}

/// The parameters of an analytic shape s.type into `s` (defaults for those not given).
void read_analytic_shape(const SceneReader& r, const std::string& p, Shape& s) {
  switch (s.type) {
    case ShapeType::kMesh:
      break;
    case ShapeType::kSphere:
      s.radius = float(r.positive(p, "radius", 1.0));
      break;
    case ShapeType::kQuad:
      s.size = read_size2(r, p, glm::vec3(2.0f, 2.0f, 0.0f));
      break;
    case ShapeType::kBox:
      if (r.has(p, "size")) {
        const std::string sp = json_pointer_child(p, "size");
        s.size = r.at(sp).is_number() ? glm::vec3(float(r.number(sp))) : r.vec3(sp);
        if (!(s.size.x > 0.0f && s.size.y > 0.0f && s.size.z > 0.0f)) {
          throw JsonFailure{sp, "sizes must be positive"};
        }
      }
      break;
    case ShapeType::kCylinder:
      s.radius = float(r.positive(p, "radius", 1.0));
      s.height = float(r.positive(p, "height", 2.0));
      break;
    case ShapeType::kSlab:
      s.size = read_size2(r, p, glm::vec3(2.0f, 2.0f, 0.0f));
      s.thickness = float(r.positive(p, "thickness", 0.1));
      break;
    case ShapeType::kHollowCylinder:
      s.radius = float(r.positive(p, "radius", 1.0));
      s.height = float(r.positive(p, "height", 2.0));
      s.thickness = float(r.positive(p, "thickness", 0.1));
      if (!(s.thickness < s.radius)) {
        throw JsonFailure{json_pointer_child(p, "thickness"),
                          "wall thickness must be smaller than the radius"};
      }
      break;
  }
}

SceneObject read_object(const SceneReader& r, const std::string& p, Scene& scene) {
  r.object(p, {"name", "shape", "file", "gimage", "gfield", "normals", "radius", "height", "size",
               "thickness", "transform", "material"});
  r.require(p, "shape");
  r.require(p, "material");
  SceneObject o;
  o.name = r.string(p, "name", "");
  Shape& s = o.shape;
  s.type = read_shape_type(r, p);
  check_shape_keys(r, p, s.type);
  if (s.type == ShapeType::kMesh)
    read_mesh_shape(r, p, scene, s);
  else
    read_analytic_shape(r, p, s);
  if (r.has(p, "transform"))
    o.transform = read_transform(r, json_pointer_child(p, "transform"));
  if (s.type != ShapeType::kMesh) {  // a mesh's reach is known once its file is read
    glm::dvec3 lo, hi;
    shape_bounds(s, lo, hi);
    const double reach = box_reach(object_to_world(o.transform), lo, hi);
    if (reach > kMaxCoordinate) {
      throw JsonFailure{p, "reaches " + SceneReader::fmt(reach) +
                               " in world coordinates after its transform (limit 1e15)"};
    }
  }
  o.material = read_material(r, json_pointer_child(p, "material"), s.type);
  return o;
}

/// A glTF file included as one object: {"shape": "gltf", "file", "name"?, "transform"?}.
SceneInclude read_include(const SceneReader& r, const std::string& p, size_t position) {
  r.object(p, {"name", "shape", "file", "transform"});
  r.require(p, "file");
  SceneInclude include;
  include.name = r.string(p, "name", "");
  include.file = r.file(json_pointer_child(p, "file"));
  if (r.has(p, "transform"))
    include.transform = read_transform(r, json_pointer_child(p, "transform"));
  include.position = position;
  include.where = p;  // made "FILE:LINE:COLUMN: path" by parse_scene
  return include;
}

void read_scene(const SceneReader& r, Scene& scene) {
  const std::string root;
  r.object(root, {"purpose", "camera", "image", "environment", "ambient", "lights", "objects"});
  scene.purpose = r.string(root, "purpose", "");
  r.require(root, "camera");
  scene.camera = read_camera(r, "/camera");
  if (r.has(root, "image")) {
    r.object("/image", {"width", "height"});
    scene.width = r.integer("/image", "width", scene.width, 1, 16384);
    scene.height = r.integer("/image", "height", scene.height, 1, 16384);
  }
  if (r.has(root, "environment"))
    scene.environment = read_environment(r, "/environment");
  scene.ambient = r.color(root, "ambient", scene.ambient);
  if (r.has(root, "lights")) {
    for (size_t i = 0; i < r.array("/lights", kMaxSceneLights).size(); ++i) {
      scene.lights.push_back(read_light(r, json_pointer_child("/lights", i)));
    }
  }
  if (r.has(root, "objects")) {
    for (size_t i = 0; i < r.array("/objects", kMaxSceneObjects).size(); ++i) {
      const std::string p = json_pointer_child("/objects", i);
      const json& o = r.at(p);
      if (o.is_object() && o.contains("shape") && o["shape"] == "gltf") {
        scene.includes.push_back(read_include(r, p, scene.objects.size()));
      } else {
        scene.objects.push_back(read_object(r, p, scene));
      }
    }
  }
}

}  // namespace

bool parse_scene(const std::string& text, const std::string& filename, Scene& scene,
                 std::string& error, OutsidePaths outside) {
  LocatedJson document;
  std::string parse_error;
  if (!parse_located_json(text, document, parse_error)) {
    error = filename + ":" + printable(parse_error);
    return false;
  }
  Scene result;
  result.filename = filename;
  const SceneReader reader(document.value, fs::path(filename).parent_path(), scene_root(filename),
                           outside);
  try {
    read_scene(reader, result);
  } catch (const JsonFailure& e) {
    const JsonLocation where = document.at(e.pointer);
    const std::string path = readable_path(e.pointer);
    error = filename + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
            ": " + printable((path.empty() ? "" : path + ": ") + e.what);
    return false;
  }
  for (SceneInclude& include : result.includes) {
    const JsonLocation where = document.at(include.where);
    include.where = filename + ":" + std::to_string(where.line) + ":" +
                    std::to_string(where.column) + ": " + readable_path(include.where);
  }
  scene = std::move(result);
  return true;
}

bool load_scene(const std::string& filename, Scene& scene, std::string& error,
                OutsidePaths outside) {
  std::string text;
  if (!read_file(filename, kMaxSceneFileBytes, text, error))
    return false;
  return parse_scene(text, filename, scene, error, outside);
}

}  // namespace gfield
