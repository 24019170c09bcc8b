// Scene files: parsing with locations, validation, and the small shared helpers (camera rays,
// transforms, textures).

#include "gfield/scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "gfield/camera_text.hpp"
#include "gfield/confined_path.hpp"
#include "gfield/file_read.hpp"
#include "gfield/image.hpp"
#include "gfield/limits.hpp"
#include "gfield/located_json.hpp"
#include "gfield/optics.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace fs = std::filesystem;
namespace {

using nlohmann::json;

/// Colours, intensities and absorption coefficients: at most this (radiance stays far inside
/// float range through any number of bounces' products).
constexpr double kMaxRadiometric = 1e6;

/// A validation failure at a JSON pointer; turned into "FILE:LINE:COL: path: message".
struct SceneError {
  std::string pointer;
  std::string message;
};

/// "/objects/2/material" -> "objects[2].material".
std::string readable_path(const std::string& pointer) {
  std::string out;
  size_t i = 0;
  while (i < pointer.size()) {
    const size_t next = pointer.find('/', i + 1);
    std::string token =
        pointer.substr(i + 1, next == std::string::npos ? std::string::npos : next - i - 1);
    const bool index = !token.empty() && std::all_of(token.begin(), token.end(), ::isdigit);
    if (index) {
      out += "[" + token + "]";
    } else {
      out += (out.empty() ? "" : ".") + token;
    }
    if (next == std::string::npos)
      break;
    i = next;
  }
  return out;
}

std::string list_names(std::initializer_list<const char*> names) {
  std::string out;
  size_t k = 0;
  for (const char* n : names) {
    if (k > 0)
      out += (k + 1 == names.size()) ? " or " : ", ";
    out += n;
    ++k;
  }
  return out;
}

/// Reads values out of the document, throwing SceneError with the value's pointer.
class Reader {
 public:
  /// `base`: the scene file's folder; `root`: the folder its files must lie in (scene_root).
  Reader(const json& root, fs::path base, fs::path files_root, OutsidePaths outside)
      : root_(root),
        base_(std::move(base)),
        files_root_(std::move(files_root)),
        outside_(outside) {}

  const json& at(const std::string& pointer) const { return root_.at(json::json_pointer(pointer)); }
  bool has(const std::string& pointer, const char* key) const { return at(pointer).contains(key); }

  /// Requires an object with only the given keys.
  void object(const std::string& pointer, std::initializer_list<const char*> keys) const {
    const json& v = at(pointer);
    if (!v.is_object())
      throw SceneError{pointer, "expected an object"};
    for (auto it = v.begin(); it != v.end(); ++it) {
      const bool known =
          std::any_of(keys.begin(), keys.end(), [&](const char* k) { return it.key() == k; });
      if (!known) {
        throw SceneError{json_pointer_child(pointer, it.key()),
                         "unknown key \"" + it.key() + "\" (expected " + list_names(keys) + ")"};
      }
    }
  }

  void require(const std::string& pointer, const char* key) const {
    if (!has(pointer, key)) {
      throw SceneError{pointer, std::string("missing key \"") + key + "\""};
    }
  }

  /// A number, any finite value (the JSON parser refuses the others).
  double raw_number(const std::string& pointer) const {
    const json& v = at(pointer);
    if (!v.is_number())
      throw SceneError{pointer, "expected a number"};
    return v.get<double>();
  }
  /// A number within +-kMaxCoordinate (every number of a scene without a range of its own).
  double number(const std::string& pointer) const {
    const double d = raw_number(pointer);
    if (std::abs(d) > kMaxCoordinate)
      throw SceneError{pointer, "number " + fmt(d) + " is beyond the limit of 1e15"};
    return d;
  }
  /// A number in [lo, hi] (`range`: the interval as the docs write it, e.g. "[0, 1e6]");
  /// `what` names it in the message ("must be in ..." when empty).
  double in_range(const std::string& pointer, double lo, double hi, const char* range,
                  const std::string& what = "") const {
    const double d = raw_number(pointer);
    if (!(d >= lo && d <= hi)) {
      throw SceneError{pointer, (what.empty() ? "" : what + " ") + "must be in " + range + " (is " +
                                    fmt(d) + ")"};
    }
    return d;
  }
  /// [x, y, z] or one number for all three, each in [lo, hi] (`range`, `what`: as in_range).
  glm::dvec3 vec3_in_range(const std::string& pointer, double lo, double hi, const char* range,
                           const std::string& what) const {
    const json& v = at(pointer);
    if (v.is_number())
      return glm::dvec3(in_range(pointer, lo, hi, range, what));
    if (!v.is_array() || v.size() != 3)
      throw SceneError{pointer, "expected a number or [x, y, z]"};
    glm::dvec3 out;
    for (int i = 0; i < 3; ++i)
      out[i] = raw_number(json_pointer_child(pointer, size_t(i)));
    if (glm::any(glm::lessThan(out, glm::dvec3(lo))) ||
        glm::any(glm::greaterThan(out, glm::dvec3(hi)))) {
      throw SceneError{pointer, what + " must be in " + range + " (are " + fmt(out.x) + ", " +
                                    fmt(out.y) + ", " + fmt(out.z) + ")"};
    }
    return out;
  }
  double number(const std::string& pointer, const char* key, double fallback) const {
    return has(pointer, key) ? number(json_pointer_child(pointer, key)) : fallback;
  }
  double positive(const std::string& pointer, const char* key, double fallback) const {
    const double v = number(pointer, key, fallback);
    if (!(v > 0.0)) {
      throw SceneError{json_pointer_child(pointer, key), "must be positive (is " + fmt(v) + ")"};
    }
    return v;
  }
  int integer(const std::string& pointer, const char* key, int fallback, int lo, int hi) const {
    if (!has(pointer, key))
      return fallback;
    const std::string p = json_pointer_child(pointer, key);
    const json& v = at(p);
    if (!v.is_number_integer())
      throw SceneError{p, "expected an integer"};
    const auto i = v.get<long long>();
    if (i < lo || i > hi) {
      throw SceneError{p, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                              "] (is " + std::to_string(i) + ")"};
    }
    return int(i);
  }
  std::string string(const std::string& pointer) const {
    const json& v = at(pointer);
    if (!v.is_string())
      throw SceneError{pointer, "expected a string"};
    return v.get<std::string>();
  }
  std::string string(const std::string& pointer, const char* key,
                     const std::string& fallback) const {
    return has(pointer, key) ? string(json_pointer_child(pointer, key)) : fallback;
  }
  glm::vec3 vec3(const std::string& pointer) const {
    const json& v = at(pointer);
    if (!v.is_array() || v.size() != 3)
      throw SceneError{pointer, "expected [x, y, z]"};
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
      out[i] = float(number(json_pointer_child(pointer, size_t(i))));
    return out;
  }
  glm::vec3 vec3(const std::string& pointer, const char* key, glm::vec3 fallback) const {
    return has(pointer, key) ? vec3(json_pointer_child(pointer, key)) : fallback;
  }
  /// A colour: [r, g, b] or one number for grey; components in [0, kMaxRadiometric].
  glm::vec3 color(const std::string& pointer) const {
    return glm::vec3(vec3_in_range(pointer, 0.0, kMaxRadiometric, "[0, 1e6]", "colour components"));
  }
  glm::vec3 color(const std::string& pointer, const char* key, glm::vec3 fallback) const {
    return has(pointer, key) ? color(json_pointer_child(pointer, key)) : fallback;
  }
  /// An intensity in [0, kMaxRadiometric] (default 1).
  double intensity(const std::string& pointer) const {
    return has(pointer, "intensity") ? in_range(json_pointer_child(pointer, "intensity"), 0.0,
                                                kMaxRadiometric, "[0, 1e6]")
                                     : 1.0;
  }
  /// An array of at most `max` elements.
  const json& array(const std::string& pointer, size_t max) const {
    const json& v = at(pointer);
    if (!v.is_array())
      throw SceneError{pointer, "expected an array"};
    if (v.size() > max) {
      throw SceneError{pointer, std::to_string(v.size()) + " elements, more than the limit of " +
                                    std::to_string(max)};
    }
    return v;
  }
  /// A file path relative to the scene file, inside the scene's root unless outside paths are
  /// allowed (confined_path.hpp); must exist.
  std::string file(const std::string& pointer) const {
    const std::string name = string(pointer);
    if (name.empty())
      throw SceneError{pointer, "empty file name"};
    std::string path, problem;
    if (!resolve_named_path(base_, name, files_root_, outside_, path, problem))
      throw SceneError{pointer, problem};
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
      throw SceneError{pointer, "file not found: " + path};
    }
    return path;
  }
  OutsidePaths outside() const { return outside_; }

  /// The shortest text of `v` that reads back exactly (a value just past a bound shows it).
  static std::string fmt(double v) { return double_text(v); }

 private:
  const json& root_;
  fs::path base_;
  fs::path files_root_;
  OutsidePaths outside_;
};

Camera read_camera(const Reader& r, const std::string& p) {
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
    throw SceneError{key.empty() ? p : json_pointer_child(p, key), problem};
  return c;
}

EnvironmentDesc read_environment(const Reader& r, const std::string& p) {
  r.object(p, {"type", "color", "intensity", "file", "faces"});
  EnvironmentDesc e;
  const std::string type = r.string(p, "type", "studio");
  e.intensity = float(r.intensity(p));
  auto forbid = [&](const char* key) {
    if (r.has(p, key)) {
      throw SceneError{
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
      throw SceneError{fp, "expected 6 files in the order +X, -X, +Y, -Y, +Z, -Z"};
    }
    for (size_t f = 0; f < 6; ++f)
      e.faces[f] = r.file(json_pointer_child(fp, f));
    forbid("color");
    forbid("file");
  } else {
    throw SceneError{json_pointer_child(p, "type"),
                     "unknown environment type \"" + type + "\" (expected " +
                         list_names({"studio", "constant", "equirect", "cube"}) + ")"};
  }
  return e;
}

Light read_light(const Reader& r, const std::string& p) {
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
      throw SceneError{json_pointer_child(p, "position"), "a directional light has no position"};
    }
    const glm::vec3 d = r.vec3(json_pointer_child(p, "direction"));
    if (glm::length(d) <= 0.0f)
      throw SceneError{json_pointer_child(p, "direction"), "zero direction"};
    l.direction = glm::normalize(d);
  } else if (type == "point") {
    l.type = LightType::kPoint;
    r.require(p, "position");
    if (r.has(p, "direction")) {
      throw SceneError{json_pointer_child(p, "direction"), "a point light has no direction"};
    }
    l.position = r.vec3(json_pointer_child(p, "position"));
  } else {
    throw SceneError{json_pointer_child(p, "type"),
                     "unknown light type \"" + type + "\" (expected directional or point)"};
  }
  return l;
}

/// The "texture" of a diffuse material: none, checker or color-chart on analytic shapes; mesh or
/// none on meshes (default: none; the mesh's own base colour is chosen once the mesh is read).
TextureType read_texture(const Reader& r, const std::string& p, ShapeType shape) {
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
    throw SceneError{tp, mesh ? "a mesh takes \"mesh\" (its own texture, vertex or material "
                                "colours) or \"none\"; procedural textures apply to analytic "
                                "shapes"
                              : "\"mesh\" applies to meshes (analytic shapes take none, "
                                "checker or color-chart)"};
  }
  throw SceneError{tp, "unknown texture \"" + texture + "\" (expected " +
                           (mesh ? "mesh or none" : "none, checker or color-chart") + ")"};
}

Material read_material(const Reader& r, const std::string& p, ShapeType shape) {
  r.object(p, {"type", "color", "texture", "colors", "scale", "tint", "ior", "absorption"});
  r.require(p, "type");
  Material m;
  const std::string type = r.string(json_pointer_child(p, "type"));
  auto only = [&](std::initializer_list<const char*> allowed) {
    for (const char* key : {"color", "texture", "colors", "scale", "tint", "ior", "absorption"}) {
      const bool ok = std::any_of(allowed.begin(), allowed.end(),
                                  [&](const char* a) { return std::string(a) == key; });
      if (!ok && r.has(p, key)) {
        throw SceneError{json_pointer_child(p, key),
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
          throw SceneError{json_pointer_child(p, key),
                           std::string("\"") + key + "\" applies to the checker texture only"};
        }
      }
    }
    if (r.has(p, "colors")) {
      const std::string cp = json_pointer_child(p, "colors");
      if (!r.at(cp).is_array() || r.at(cp).size() != 2) {
        throw SceneError{cp, "expected two colours"};
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
        throw SceneError{sp, "expected a number or [squares along u, squares along v]"};
      }
      if (!(m.checker_scale.x > 0.0f && m.checker_scale.y > 0.0f)) {
        throw SceneError{sp, "must be positive"};
      }
    }
  } else if (type == "mirror") {
    m.type = MaterialType::kMirror;
    only({"tint"});
    m.color = r.color(p, "tint", glm::vec3(1.0f));
  } else if (type == "dielectric") {
    m.type = MaterialType::kDielectric;
    only({"ior", "absorption"});
    if (!shape_is_closed(shape)) {
      throw SceneError{p, std::string("a dielectric needs a closed shape (a ") + shape_name(shape) +
                              " bounds no volume)"};
    }
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
        throw SceneError{
            ip, "unknown refractive index preset \"" + m.ior_preset + "\" (known: " + names + ")"};
      }
      m.ior = *index;
    } else {
      m.ior = float(r.in_range(ip, kMinIor, kMaxIor, "[1e-6, 1e6]", "an index of refraction"));
    }
    m.absorption = r.color(p, "absorption", m.absorption);
  } else {
    throw SceneError{
        json_pointer_child(p, "type"),
        "unknown material type \"" + type + "\" (expected diffuse, mirror or dielectric)"};
  }
  return m;
}

Transform read_transform(const Reader& r, const std::string& p) {
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
  std::error_code ec;
  return fs::is_regular_file(candidate, ec) ? candidate.string() : std::string();
}

SceneObject read_object(const Reader& r, const std::string& p, Scene& scene) {
  r.object(p, {"name", "shape", "file", "gimage", "gfield", "normals", "radius", "height", "size",
               "thickness", "transform", "material"});
  r.require(p, "shape");
  r.require(p, "material");
  SceneObject o;
  o.name = r.string(p, "name", "");
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
    throw SceneError{json_pointer_child(p, "shape"),
                     "unknown shape \"" + shape + "\" (expected " +
                         list_names({"mesh", "sphere", "quad", "box", "cylinder", "slab",
                                     "hollow-cylinder", "gltf"}) +
                         ")"};
  }
  Shape& s = o.shape;
  s.type = found->second;
  // Which parameters each shape takes.
  std::set<std::string> allowed = {"name", "shape", "transform", "material"};
  switch (s.type) {
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
      throw SceneError{json_pointer_child(p, it.key()),
                       "\"" + it.key() + "\" does not apply to a " + shape};
    }
  }
  auto size2 = [&](glm::vec3 fallback) {
    if (!r.has(p, "size"))
      return fallback;
    const std::string sp = json_pointer_child(p, "size");
    const json& v = r.at(sp);
    if (!v.is_array() || v.size() != 2)
      throw SceneError{sp, "expected [width, height]"};
    glm::vec3 out(float(r.number(json_pointer_child(sp, size_t(0)))),
                  float(r.number(json_pointer_child(sp, size_t(1)))), 0.0f);
    if (!(out.x > 0.0f && out.y > 0.0f))
      throw SceneError{sp, "sizes must be positive"};
    return out;
  };
  switch (s.type) {
    case ShapeType::kMesh: {
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
        throw SceneError{json_pointer_child(p, "normals"), "expected \"smooth\" or \"flat\""};
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
      } else {
        if ((r.has(p, "gimage") && same->geometry_image != asset.geometry_image) ||
            (r.has(p, "gfield") && same->geometry_field != asset.geometry_field)) {
          throw SceneError{p, "instances of one mesh file must name the same gimage/gfield"};
        }
        s.mesh = int(same - scene.meshes.begin());
      }
      break;
    }
    case ShapeType::kSphere:
      s.radius = float(r.positive(p, "radius", 1.0));
      break;
    case ShapeType::kQuad:
      s.size = size2(glm::vec3(2.0f, 2.0f, 0.0f));
      break;
    case ShapeType::kBox:
      if (r.has(p, "size")) {
        const std::string sp = json_pointer_child(p, "size");
        s.size = r.at(sp).is_number() ? glm::vec3(float(r.number(sp))) : r.vec3(sp);
        if (!(s.size.x > 0.0f && s.size.y > 0.0f && s.size.z > 0.0f)) {
          throw SceneError{sp, "sizes must be positive"};
        }
      }
      break;
    case ShapeType::kCylinder:
      s.radius = float(r.positive(p, "radius", 1.0));
      s.height = float(r.positive(p, "height", 2.0));
      break;
    case ShapeType::kSlab:
      s.size = size2(glm::vec3(2.0f, 2.0f, 0.0f));
      s.thickness = float(r.positive(p, "thickness", 0.1));
      break;
    case ShapeType::kHollowCylinder:
      s.radius = float(r.positive(p, "radius", 1.0));
      s.height = float(r.positive(p, "height", 2.0));
      s.thickness = float(r.positive(p, "thickness", 0.1));
      if (!(s.thickness < s.radius)) {
        throw SceneError{json_pointer_child(p, "thickness"),
                         "wall thickness must be smaller than the radius"};
      }
      break;
  }
  if (r.has(p, "transform"))
    o.transform = read_transform(r, json_pointer_child(p, "transform"));
  if (s.type != ShapeType::kMesh) {  // a mesh's reach is known once its file is read
    glm::dvec3 lo, hi;
    shape_bounds(s, lo, hi);
    const double reach = box_reach(object_to_world(o.transform), lo, hi);
    if (reach > kMaxCoordinate) {
      throw SceneError{p, "reaches " + Reader::fmt(reach) +
                              " in world coordinates after its transform (limit 1e15)"};
    }
  }
  o.material = read_material(r, json_pointer_child(p, "material"), s.type);
  return o;
}

/// A glTF file included as one object: {"shape": "gltf", "file", "name"?, "transform"?}.
SceneInclude read_include(const Reader& r, const std::string& p, size_t position) {
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

void read_scene(const Reader& r, Scene& scene) {
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

bool shape_is_closed(ShapeType type) {
  return type != ShapeType::kQuad;
}

const char* shape_name(ShapeType type) {
  switch (type) {
    case ShapeType::kMesh:
      return "mesh";
    case ShapeType::kSphere:
      return "sphere";
    case ShapeType::kQuad:
      return "quad";
    case ShapeType::kBox:
      return "box";
    case ShapeType::kCylinder:
      return "cylinder";
    case ShapeType::kSlab:
      return "slab";
    case ShapeType::kHollowCylinder:
      return "hollow-cylinder";
  }
  return "?";
}

CameraRay camera_ray(const Camera& camera, int width, int height, glm::dvec2 pixel) {
  const glm::dvec3 position(camera.position);
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tan_half = std::tan(glm::radians(double(camera.fov_degrees)) * 0.5);
  const double aspect = double(width) / double(height);
  const double sx = (2.0 * pixel.x / double(width) - 1.0) * tan_half * aspect;
  const double sy = (1.0 - 2.0 * pixel.y / double(height)) * tan_half;
  return {position, glm::normalize(forward + sx * right + sy * up)};
}

glm::dmat4 object_to_world(const Transform& transform) {
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(transform.translate));
  m = glm::rotate(m, glm::radians(double(transform.rotate_degrees.z)), glm::dvec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(double(transform.rotate_degrees.y)), glm::dvec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(double(transform.rotate_degrees.x)), glm::dvec3(1, 0, 0));
  return glm::scale(m, glm::dvec3(transform.scale));
}

bool transform_from_matrix(const glm::dmat4& matrix, Transform& transform, double& residual) {
  const glm::dmat3 linear(matrix);
  if (!(glm::determinant(linear) > 0.0)) {
    return false;
  }
  // Scale = column lengths; rotation = the columns orthonormalised (Gram-Schmidt), so that a
  // shear shows as a residual instead of a rotation that is not one.
  glm::dvec3 scale(glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2]));
  glm::dmat3 rotation;
  rotation[0] = linear[0] / scale.x;
  rotation[1] = glm::normalize(linear[1] - glm::dot(linear[1], rotation[0]) * rotation[0]);
  rotation[2] = glm::cross(rotation[0], rotation[1]);
  // R = Rz(z) Ry(y) Rx(x); element (row, column) is rotation[column][row].
  const double sy = std::clamp(-rotation[0][2], -1.0, 1.0);
  glm::dvec3 angles(0.0, std::asin(sy), 0.0);
  if (std::abs(sy) < 1.0 - 1e-12) {
    angles.x = std::atan2(rotation[1][2], rotation[2][2]);
    angles.z = std::atan2(rotation[0][1], rotation[0][0]);
  } else {
    angles.z = std::atan2(-rotation[1][0], rotation[1][1]);
  }
  transform.translate = glm::vec3(matrix[3]);
  transform.rotate_degrees = glm::vec3(glm::degrees(angles));
  transform.scale = glm::vec3(scale);
  const glm::dmat3 recomposed(object_to_world(transform));
  residual = 0.0;
  for (int c = 0; c < 3; ++c) {
    residual = std::max(residual, glm::length(recomposed[c] - linear[c]));
  }
  residual /= std::max({scale.x, scale.y, scale.z});
  return true;
}

void shape_bounds(const Shape& shape, glm::dvec3& lo, glm::dvec3& hi) {
  glm::dvec3 half(0.0);
  switch (shape.type) {
    case ShapeType::kMesh:
      break;
    case ShapeType::kSphere:
      half = glm::dvec3(shape.radius);
      break;
    case ShapeType::kQuad:
      half = glm::dvec3(0.5 * shape.size.x, 0.5 * shape.size.y, 0.0);
      break;
    case ShapeType::kBox:
      half = 0.5 * glm::dvec3(shape.size);
      break;
    case ShapeType::kSlab:
      half = 0.5 * glm::dvec3(shape.size.x, shape.size.y, shape.thickness);
      break;
    case ShapeType::kCylinder:
    case ShapeType::kHollowCylinder:
      half = glm::dvec3(shape.radius, 0.5 * shape.height, shape.radius);
      break;
  }
  lo = -half;
  hi = half;
}

double box_reach(const glm::dmat4& m, glm::dvec3 lo, glm::dvec3 hi) {
  double reach = 0.0;
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    const glm::dvec3 w = glm::dvec3(m * glm::dvec4(corner, 1.0));
    reach = std::max({reach, std::abs(w.x), std::abs(w.y), std::abs(w.z)});
  }
  return reach;
}

glm::vec3 texture_albedo(const Material& material, glm::vec2 uv) {
  switch (material.texture) {
    case TextureType::kNone:
    case TextureType::kMesh:  // the mesh's own base colour multiplies it (mesh_appearance.hpp)
      return material.color;
    case TextureType::kChecker: {
      // The squares' parity in double: a scale of 1e10 (a telephoto view of a checker) takes the
      // square indices beyond int. The products stay float, as the shader's.
      const double cu = std::floor(uv.x * material.checker_scale.x);
      const double cv = std::floor(uv.y * material.checker_scale.y);
      return material.checker_colors[std::fmod(std::fabs(cu + cv), 2.0) == 1.0 ? 1 : 0];
    }
    case TextureType::kColorChart: {
      // ColorChecker Classic, sRGB 8-bit values, rows from the top.
      static const unsigned char kPatches[24][3] = {
          {115, 82, 68},   {194, 150, 130}, {98, 122, 157}, {87, 108, 67},   {133, 128, 177},
          {103, 189, 170}, {214, 126, 44},  {80, 91, 166},  {193, 90, 99},   {94, 60, 108},
          {157, 188, 64},  {224, 163, 46},  {56, 61, 150},  {70, 148, 73},   {175, 54, 60},
          {231, 199, 31},  {187, 86, 149},  {8, 133, 161},  {243, 243, 242}, {200, 200, 200},
          {160, 160, 160}, {122, 122, 121}, {85, 85, 85},   {52, 52, 52}};
      const float u = std::clamp(uv.x, 0.0f, 1.0f) * 6.0f;
      const float v = std::clamp(1.0f - uv.y, 0.0f, 1.0f) * 4.0f;
      const int column = std::min(int(u), 5);
      const int row = std::min(int(v), 3);
      const float fu = u - float(column), fv = v - float(row);
      constexpr float kGap = 0.08f;  // black border around each patch, fraction of a cell
      if (fu < kGap || fu > 1.0f - kGap || fv < kGap || fv > 1.0f - kGap) {
        return glm::vec3(0.01f);
      }
      const unsigned char* c = kPatches[row * 6 + column];
      return glm::vec3(srgb_to_linear(c[0] / 255.0f), srgb_to_linear(c[1] / 255.0f),
                       srgb_to_linear(c[2] / 255.0f));
    }
  }
  return material.color;
}

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
  const Reader reader(document.value, fs::path(filename).parent_path(), scene_root(filename),
                      outside);
  try {
    read_scene(reader, result);
  } catch (const SceneError& e) {
    const JsonLocation where = document.at(e.pointer);
    const std::string path = readable_path(e.pointer);
    error = filename + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
            ": " + printable((path.empty() ? "" : path + ": ") + e.message);
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

bool use_asset_folder(const std::string& dir, Scene& scene, std::string& error) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    error = dir + ": not a folder";
    return false;
  }
  for (MeshAsset& mesh : scene.meshes) {
    const std::string stem = (fs::path(dir) / mesh.asset).string();
    if (fs::is_regular_file(stem + ".gimage.exr", ec))
      mesh.geometry_image = stem + ".gimage.exr";
    if (fs::is_regular_file(stem + ".gfield.exr", ec))
      mesh.geometry_field = stem + ".gfield.exr";
  }
  return true;
}

}  // namespace gfield
