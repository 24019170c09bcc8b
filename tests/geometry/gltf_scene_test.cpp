// glTF 2.0 files as scenes: a hand-written file with a node hierarchy, a
// camera, KHR_lights_punctual lights and the three material mappings (transmission + ior +
// volume -> dielectric, metallic 1 roughness 0 -> mirror, otherwise diffuse with the mesh's own
// base colour), each expected value worked out by hand from the glTF specification; a JSON
// scene including the file as one object; the JSON "texture" defaults of meshes. (The
// glass gives thicknessFactor 1, a volume: without it KHR_materials_volume is thin-walled, and
// roughness 0, whose default 1 would be a frosted glass that gfield renders smooth.)

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "geometry/scene_file.hpp"
#include "gfield/scene.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kDir = fs::path(gfield::build_paths::test_tmp()) / "gltf_scene";

/// scene.gltf: a tetrahedron (tet.bin) as three meshes (glass, mirror, diffuse) and these nodes:
/// 0 parent (translation (1, 0, 0), 90 degrees about +Y) of 1 (the glass tetrahedron, translation
/// (0, 2, 0), scale 2); 2 the camera at (0, 1, 5) looking down -Z, yfov 0.5 rad; 3 a point light
/// at (0, 3, 0); 4 a directional light shining down -Z; 5 the mirror; 6 the diffuse mesh.
fs::path write_scene_gltf() {
  const float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::uint16_t indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  std::string bin(72, '\0');
  std::memcpy(bin.data(), positions, 48);
  std::memcpy(bin.data() + 48, indices, 24);
  test::write_file(kDir / "tet.bin", bin);
  const double s = std::sqrt(0.5);
  json d = json::parse(R"({
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 2, 3, 4, 5, 6]}],
    "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_transmission", "KHR_materials_ior",
                       "KHR_materials_volume"],
    "nodes": [
      {"name": "parent", "translation": [1, 0, 0], "children": [1]},
      {"name": "glass", "mesh": 0, "translation": [0, 2, 0], "scale": [2, 2, 2]},
      {"camera": 0, "translation": [0, 1, 5]},
      {"translation": [0, 3, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
      {"extensions": {"KHR_lights_punctual": {"light": 1}}},
      {"name": "mirror", "mesh": 1},
      {"name": "diffuse", "mesh": 2, "translation": [0, 0, -3]}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1,
                                                         "aspectRatio": 2.0}}],
    "extensions": {"KHR_lights_punctual": {"lights": [
      {"type": "point", "intensity": 2.0, "color": [1, 0.5, 0.25]},
      {"type": "directional", "intensity": 0.5}]}},
    "materials": [
      {"pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0},
       "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
                      "KHR_materials_ior": {"ior": 1.33},
                      "KHR_materials_volume": {"thicknessFactor": 1,
                                               "attenuationColor": [0.5, 1, 0.25],
                                               "attenuationDistance": 2}}},
      {"pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.7, 1], "metallicFactor": 1,
                                "roughnessFactor": 0.02}},
      {"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1], "metallicFactor": 0,
                                "roughnessFactor": 0.8}}],
    "meshes": [
      {"name": "glass", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]},
      {"name": "mirror", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 1}]},
      {"name": "diffuse", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 2}]}],
    "accessors": [
      {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
       "min": [0, 0, 0], "max": [1, 1, 1]},
      {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                    {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
    "buffers": [{"uri": "tet.bin", "byteLength": 72}]})");
  d["nodes"][0]["rotation"] = {0.0, s, 0.0, s};  // 90 degrees about +Y (x, y, z, w)
  const fs::path file = kDir / "scene.gltf";
  test::write_file(file, d.dump());
  return file;
}

void expect_near(glm::vec3 got, glm::dvec3 want, double tolerance) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

/// The object named `name` (a failure and the first object when there is none).
const SceneObject& named(const Scene& scene, const std::string& name) {
  for (const SceneObject& o : scene.objects)
    if (o.name == name)
      return o;
  ADD_FAILURE() << "no object " << name;
  return scene.objects.front();
}

/// Object point `p` in world coordinates.
glm::dvec3 to_world(const SceneObject& o, glm::dvec3 p) {
  return glm::dvec3(object_to_world(o.transform) * glm::dvec4(p, 1.0));
}

TEST(GltfScene, HierarchyCameraLightsAndMaterials) {
  const fs::path file = write_scene_gltf();
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  ASSERT_TRUE(load_scene_file(file.string(), scene, warnings, error)) << error;
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(scene.objects.size(), 3u);
  ASSERT_EQ(scene.meshes.size(), 3u);

  // Glass: world = T(1,0,0) R_y(90) T(0,2,0) S(2). Object (1,0,0) -> S (2,0,0) -> T (2,2,0) ->
  // R_y(90) (x, z) -> (z, -x): (0,2,-2) -> T (1,2,-2). Object (0,0,1) -> (0,0,2) -> (0,2,2) ->
  // (2,2,0) -> (3,2,0).
  const SceneObject& glass = named(scene, "glass");
  EXPECT_EQ(glass.material.type, MaterialType::kDielectric);
  EXPECT_NEAR(glass.material.ior, 1.33, 1e-6);
  // Beer-Lambert: attenuationColor c after attenuationDistance d: absorption -ln(c) / d.
  expect_near(glass.material.absorption, {std::log(2.0) / 2.0, 0.0, std::log(4.0) / 2.0}, 1e-6);
  expect_near(glm::vec3(to_world(glass, {0, 0, 0})), {1, 2, 0}, 1e-5);
  expect_near(glm::vec3(to_world(glass, {1, 0, 0})), {1, 2, -2}, 1e-5);
  expect_near(glm::vec3(to_world(glass, {0, 0, 1})), {3, 2, 0}, 1e-5);

  const SceneObject& mirror = named(scene, "mirror");
  EXPECT_EQ(mirror.material.type, MaterialType::kMirror);
  expect_near(mirror.material.color, {0.9, 0.8, 0.7}, 1e-6);

  const SceneObject& diffuse = named(scene, "diffuse");
  EXPECT_EQ(diffuse.material.type, MaterialType::kDiffuse);
  EXPECT_EQ(diffuse.material.texture, TextureType::kMesh);  // its base colour factor
  expect_near(glm::vec3(to_world(diffuse, {0, 1, 0})), {0, 1, -3}, 1e-6);

  // The camera node: at (0, 1, 5) looking down -Z; yfov in radians; the aspect ratio sets the
  // image's height (default width 512).
  expect_near(scene.camera.position, {0, 1, 5}, 1e-6);
  expect_near(glm::normalize(scene.camera.target - scene.camera.position), {0, 0, -1}, 1e-6);
  EXPECT_NEAR(scene.camera.fov_degrees, 0.5 * 180.0 / M_PI, 1e-4);
  EXPECT_EQ(scene.width, 2 * scene.height);

  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[0].type, LightType::kPoint);
  expect_near(scene.lights[0].position, {0, 3, 0}, 1e-6);
  expect_near(scene.lights[0].color, {1, 0.5, 0.25}, 1e-6);
  EXPECT_FLOAT_EQ(scene.lights[0].intensity, 2.0f);
  EXPECT_EQ(scene.lights[1].type, LightType::kDirectional);
  expect_near(scene.lights[1].direction, {0, 0, -1}, 1e-6);
  EXPECT_FLOAT_EQ(scene.lights[1].intensity, 0.5f);
}

TEST(GltfScene, JsonSceneIncludesAGltfFileAsOneObject) {
  const fs::path gltf = write_scene_gltf();
  const fs::path file = kDir / "include.json";
  test::write_file(file, R"({"camera": {"position": [0, 0, 10], "target": [0, 0, 0]},
    "objects": [{"name": "ball", "shape": "sphere", "radius": 0.5,
                 "material": {"type": "diffuse"}},
                {"name": "tets", "shape": "gltf", "file": "scene.gltf",
                 "transform": {"translate": [0, 10, 0]}}]})");
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  ASSERT_TRUE(load_scene_file(file.string(), scene, warnings, error)) << error;
  ASSERT_EQ(scene.objects.size(), 4u);  // the sphere, then the file's three mesh nodes
  EXPECT_EQ(scene.objects[0].shape.type, ShapeType::kSphere);
  // Named "INCLUDE/NODE"; the include's transform goes after the node's world matrix.
  EXPECT_EQ(named(scene, "tets/glass").material.type, MaterialType::kDielectric);
  expect_near(glm::vec3(to_world(named(scene, "tets/glass"), {0, 0, 0})), {1, 12, 0}, 1e-5);
  EXPECT_TRUE(scene.lights.empty());  // an included file's lights and cameras are not used
  expect_near(scene.camera.position, {0, 0, 10}, 0.0);
}

TEST(GltfScene, MeshTextureDefaultsOfJsonScenes) {
  const std::string mesh = std::string(gfield::build_paths::mesh_dir()) + "/spot-painted.obj";
  const std::string plain = std::string(gfield::build_paths::mesh_dir()) + "/torus.obj";
  const fs::path file = kDir / "defaults.json";
  test::write_file(file, R"({"camera": {"position": [0, 0, 10], "target": [0, 0, 0]}, "objects": [
    {"shape": "mesh", "file": ")" +
                             mesh + R"(", "material": {"type": "diffuse"}},
    {"shape": "mesh", "file": ")" +
                             mesh + R"(",
     "material": {"type": "diffuse", "color": [0.5, 0.25, 1]}},
    {"shape": "mesh", "file": ")" +
                             mesh + R"(",
     "material": {"type": "diffuse", "texture": "none"}},
    {"shape": "mesh", "file": ")" +
                             plain + R"(", "material": {"type": "diffuse"}}]})");
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  // It names the bundled meshes by absolute path.
  ASSERT_TRUE(load_scene_file(file.string(), scene, warnings, error, OutsidePaths::kAllowed))
      << error;
  ASSERT_EQ(scene.objects.size(), 4u);
  // A mesh that carries a base colour takes it by default, with colour 1 ...
  EXPECT_EQ(scene.objects[0].material.texture, TextureType::kMesh);
  expect_near(scene.objects[0].material.color, {1, 1, 1}, 0.0);
  // ... that "color" multiplies ...
  EXPECT_EQ(scene.objects[1].material.texture, TextureType::kMesh);
  expect_near(scene.objects[1].material.color, {0.5, 0.25, 1}, 0.0);
  // ... and "texture": "none" ignores (plain colour, the default 0.8).
  EXPECT_EQ(scene.objects[2].material.texture, TextureType::kNone);
  expect_near(scene.objects[2].material.color, {0.8, 0.8, 0.8}, 1e-6);
  // A mesh without a base colour of its own keeps the plain default.
  EXPECT_EQ(scene.objects[3].material.texture, TextureType::kNone);
  expect_near(scene.objects[3].material.color, {0.8, 0.8, 0.8}, 1e-6);
}

}  // namespace
}  // namespace gfield
