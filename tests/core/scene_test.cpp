// Scene files: parsing, instancing, asset discovery, and errors with file:line:column.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <stb/stb_image_write.h>
#include <glm/gtc/matrix_transform.hpp>

#include "gfield/environment.hpp"
#include "gfield/image.hpp"
#include "gfield/scene.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const std::string kSpot = std::string(gfield::build_paths::data_dir()) + "/meshes/spot.obj";

/// A scene in the test folder (so relative paths resolve from there).
std::string scene_path(const std::string& name) {
  return (fs::path(gfield::build_paths::test_tmp()) / name).string();
}

/// The tests' scenes name the bundled meshes by absolute path: outside paths allowed.
bool parse(const std::string& text, Scene& scene, std::string& error) {
  return parse_scene(text, scene_path("scene.json"), scene, error, OutsidePaths::kAllowed);
}

/// A scene text with '@' where its error lies, and what the error says there.
struct BadScene {
  std::string text;
  std::string what;
};

/// Expects the scene without its '@' to fail with a message that starts with
/// "FILE:LINE:COLUMN:", the position of the '@', and contains `what`.
void expect_error(const BadScene& bad) {
  const size_t at = bad.text.find('@');
  ASSERT_NE(at, std::string::npos) << bad.text;
  const std::string text = bad.text.substr(0, at) + bad.text.substr(at + 1);
  const size_t line = 1 + size_t(std::count(text.begin(), text.begin() + long(at), '\n'));
  const size_t newline = at == 0 ? std::string::npos : text.rfind('\n', at - 1);
  const size_t column = newline == std::string::npos ? at + 1 : at - newline;
  Scene scene;
  std::string error;
  ASSERT_FALSE(parse(text, scene, error)) << text;
  const std::string prefix =
      scene_path("scene.json") + ":" + std::to_string(line) + ":" + std::to_string(column) + ":";
  EXPECT_EQ(error.rfind(prefix, 0), 0u) << "error: " << error << "\nexpected prefix: " << prefix;
  EXPECT_NE(error.find(bad.what), std::string::npos) << "error: " << error;
}

const char* kCamera = R"("camera": {"position": [0, 1, 5], "target": [0, 0, 0]})";

TEST(Scene, ParsesEveryPart) {
  const std::string text = std::string("{\n") + R"("purpose": "test",
)" + kCamera + R"(,
"image": {"width": 64, "height": 32},
"environment": {"type": "constant", "color": [0.5, 0.25, 1], "intensity": 2},
"ambient": 0.1,
"lights": [{"type": "directional", "direction": [0, -2, 0]},
           {"type": "point", "position": [1, 2, 3], "color": 0.5, "intensity": 4}],
"objects": [
  {"shape": "mesh", "file": ")" +
                           kSpot + R"(", "material": {"type": "mirror", "tint": 0.9}},
  {"shape": "mesh", "file": ")" +
                           kSpot + R"(", "normals": "flat",
   "transform": {"translate": [1, 2, 3], "rotate": [0, 90, 0], "scale": [1, 2, 3]},
   "material": {"type": "dielectric", "ior": "Water", "absorption": [0.1, 0.2, 0.3]}},
  {"shape": "sphere", "radius": 0.5, "material": {"type": "dielectric", "ior": 2.4}},
  {"shape": "quad", "size": [2, 3], "material": {"type": "diffuse", "texture": "checker",
   "colors": [[1, 0, 0], 0.5], "scale": [4, 2]}},
  {"shape": "slab", "size": [2, 3], "thickness": 0.2, "material": {"type": "dielectric", "ior": 1.5}},
  {"shape": "hollow-cylinder", "radius": 1, "thickness": 0.1, "height": 3,
   "material": {"type": "diffuse", "texture": "color-chart"}}
]})";
  Scene scene;
  std::string error;
  ASSERT_TRUE(parse(text, scene, error)) << error;
  EXPECT_EQ(scene.purpose, "test");
  EXPECT_EQ(scene.width, 64);
  EXPECT_EQ(scene.height, 32);
  EXPECT_EQ(scene.environment.type, EnvironmentType::kConstant);
  EXPECT_EQ(scene.environment.color, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_FLOAT_EQ(scene.environment.intensity, 2.0f);
  EXPECT_EQ(scene.ambient, glm::vec3(0.1f));
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[0].direction, glm::vec3(0, -1, 0));  // normalised
  EXPECT_EQ(scene.lights[1].type, LightType::kPoint);
  EXPECT_EQ(scene.lights[1].color, glm::vec3(0.5f));
  ASSERT_EQ(scene.objects.size(), 6u);
  // Two objects, one mesh asset: instances.
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.objects[0].shape.mesh, 0);
  EXPECT_EQ(scene.objects[1].shape.mesh, 0);
  EXPECT_FALSE(scene.objects[1].shape.smooth_normals);
  EXPECT_NEAR(scene.objects[1].material.ior, 1.33333f, 1e-4f);
  EXPECT_EQ(scene.objects[1].material.ior_preset, "Water");
  EXPECT_EQ(scene.objects[1].transform.scale, glm::vec3(1, 2, 3));
  EXPECT_FLOAT_EQ(scene.objects[2].material.ior, 2.4f);
  EXPECT_EQ(scene.objects[3].material.checker_colors[0], glm::vec3(1, 0, 0));
  EXPECT_EQ(scene.objects[3].material.checker_colors[1], glm::vec3(0.5f));
  EXPECT_EQ(scene.objects[3].material.checker_scale, glm::vec2(4, 2));
  EXPECT_FLOAT_EQ(scene.objects[4].shape.thickness, 0.2f);
  EXPECT_EQ(scene.objects[5].shape.type, ShapeType::kHollowCylinder);
}

TEST(Scene, TransformOrderIsScaleThenRotateXYZThenTranslate) {
  Transform t;
  t.translate = {1, 2, 3};
  t.rotate_degrees = {90, 90, 0};
  t.scale = {2, 1, 1};
  const glm::dvec3 p = glm::dvec3(object_to_world(t) * glm::dvec4(1, 0, 0, 1));
  // scale: (2,0,0); rotate X 90: (2,0,0); rotate Y 90: (0,0,-2); translate.
  EXPECT_NEAR(p.x, 1.0, 1e-12);
  EXPECT_NEAR(p.y, 2.0, 1e-12);
  EXPECT_NEAR(p.z, 1.0, 1e-12);
  const glm::dvec3 q = glm::dvec3(object_to_world(t) * glm::dvec4(0, 1, 0, 1));
  // rotate X 90: (0,0,1); rotate Y 90: (1,0,0).
  EXPECT_NEAR(q.x, 2.0, 1e-12);
  EXPECT_NEAR(q.y, 2.0, 1e-12);
  EXPECT_NEAR(q.z, 3.0, 1e-12);
}

TEST(Scene, CameraRayMatchesLookAtPerspective) {
  Camera camera;
  camera.position = {1, 2, 3};
  camera.target = {0, 0.5f, -1};
  camera.fov_degrees = 50;
  const int width = 64, height = 48;
  const glm::dmat4 view =
      glm::lookAt(glm::dvec3(camera.position), glm::dvec3(camera.target), glm::dvec3(camera.up));
  const glm::dmat4 projection =
      glm::perspective(glm::radians(50.0), double(width) / double(height), 0.1, 100.0);
  for (const glm::dvec2 pixel : {glm::dvec2(32, 24), glm::dvec2(0.5, 0.5), glm::dvec2(63.5, 10)}) {
    const CameraRay ray = camera_ray(camera, width, height, pixel);
    EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-12);
    const glm::dvec4 clip = projection * view * glm::dvec4(ray.origin + 7.0 * ray.direction, 1.0);
    const double x = (clip.x / clip.w * 0.5 + 0.5) * width;
    const double y = (0.5 - clip.y / clip.w * 0.5) * height;  // row 0 at the top
    EXPECT_NEAR(x, pixel.x, 1e-9);
    EXPECT_NEAR(y, pixel.y, 1e-9);
  }
}

TEST(Scene, FindsAssetsBesideTheMeshAndResolvesRelativePaths) {
  const fs::path dir = fs::path(gfield::build_paths::test_tmp()) / "scene_assets";
  fs::create_directories(dir / "meshes");
  fs::copy_file(kSpot, dir / "meshes" / "cow.obj", fs::copy_options::overwrite_existing);
  std::ofstream(dir / "meshes" / "cow.gimage.exr") << "x";
  fs::remove(dir / "meshes" / "cow.gfield.exr");
  const std::string text = std::string("{") + kCamera + R"(, "objects": [
    {"shape": "mesh", "file": "meshes/cow.obj", "material": {"type": "diffuse"}}]})";
  Scene scene;
  std::string error;
  ASSERT_TRUE(parse_scene(text, (dir / "s.json").string(), scene, error)) << error;
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].file, (dir / "meshes" / "cow.obj").string());
  EXPECT_EQ(scene.meshes[0].geometry_image, (dir / "meshes" / "cow.gimage.exr").string());
  EXPECT_EQ(scene.meshes[0].geometry_field, "");
  // A named asset that does not exist is an error.
  const std::string named = std::string("{") + kCamera + R"(, "objects": [
    {"shape": "mesh", "file": "meshes/cow.obj", "gfield": "nope.gfield.exr",
     "material": {"type": "diffuse"}}]})";
  EXPECT_FALSE(parse_scene(named, (dir / "s.json").string(), scene, error));
  EXPECT_NE(error.find("nope.gfield.exr"), std::string::npos) << error;
}

/// A scene with the camera and `rest` after it (from a second line on).
std::string with_camera(const std::string& rest) {
  return std::string("{") + kCamera + ",\n" + rest;
}

TEST(Scene, ErrorsNameFileLineAndColumn) {
  const BadScene cases[] = {
      {"{\n  \"camera\": {\"position\": [0, 0, 1], \"target\": [0, 0, 0]}\n  @\"image\": {}\n}",
       "expected ',' or '}'"},
      {with_camera(R"(  "objets": @[]})"), "unknown key \"objets\""},
      {with_camera(R"("objects": [
  {"shape": "sphere", "material": {"type": @"glas"}}]})"),
       "unknown material type \"glas\""},
      {with_camera(R"("objects": [{"shape": "sphere",
 "material": {"type": "dielectric", "ior": @"unobtainium"}}]})"),
       "unknown refractive index preset"},
      {with_camera(
           R"("objects": [{"shape": "sphere", "material": {"type": "dielectric", "ior": @0}}]})"),
       "an index of refraction must be in [1e-6, 1e6] (is 0)"},
      {with_camera(
           R"("objects": [{"shape": "sphere", "material": {"type": "dielectric", "ior": @-1.5}}]})"),
       "must be in [1e-6, 1e6] (is -1.5)"},
      {with_camera(
           R"("objects": [{"shape": "sphere", "radius": @-1, "material": {"type": "mirror"}}]})"),
       "must be positive"},
      {with_camera(R"("objects": [{"shape": "mesh", "file": @"missing.obj",
 "material": {"type": "mirror"}}]})"),
       "file not found"},
      // A non-finite number (the only way to write NaN/inf in JSON).
      {with_camera(R"("objects": [{"shape": "sphere", "transform": {"translate": [@1e999, 0, 0]},
 "material": {"type": "mirror"}}]})"),
       "not finite"},
      // A zero scale (singular transform).
      {with_camera(R"("objects": [{"shape": "sphere", "transform": {"scale": @[1, 0, 1]},
 "material": {"type": "mirror"}}]})"),
       "must be in [1e-6, 1e6]"},
      // A dielectric quad bounds no volume.
      {with_camera(
           R"("objects": [{"shape": "quad", "material": @{"type": "dielectric", "ior": 1.5}}]})"),
       "closed shape"},
      // Keys that do not apply to a shape or material.
      {with_camera(
           R"("objects": [{"shape": "sphere", "thickness": @1, "material": {"type": "mirror"}}]})"),
       "does not apply to a sphere"},
      {R"({"camera": @{"position": [0, 0, 0], "target": [0, 0, 0]}})", "coincide"},
      {R"({"camera": {"position": [0, 0, 1], "target": [0, 0, 0], "up": @[0, 0, 2]}})", "parallel"},
      {R"({"camera": {}, @"camera": {}})", "duplicate key"},
      {with_camera(R"("image": {"width": @-4}})"), "must be in [1, 16384]"},
  };
  for (const BadScene& bad : cases) {
    expect_error(bad);
  }
}

// Each value against its own documented range, printed so that it differs visibly from the
// bound (not rounded into it, and against the documented limit, not an internal one).
TEST(Scene, ValuesAreCheckedAgainstTheirOwnRangesAndPrintedExactly) {
  const std::string light = with_camera(R"("lights": [{"type": "point", "position": [0, 0, 0], )");
  const std::string sphere = with_camera(R"("objects": [{"shape": "sphere", )");
  const BadScene cases[] = {
      {light + R"("intensity": @1000000.4}]})",
       "lights[0].intensity: must be in [0, 1e6] (is 1000000.4)"},
      {light + R"("intensity": @1e30}]})", "must be in [0, 1e6] (is 1e+30)"},
      {light + R"("color": @[1, 1e30, 0]}]})",
       "colour components must be in [0, 1e6] (are 1, 1e+30, 0)"},
      {sphere + R"("transform": {"scale": @1e30}, "material": {"type": "mirror"}}]})",
       "must be in [1e-6, 1e6] (is 1e+30)"},
      {sphere + R"("material": {"type": "dielectric", "ior": @1e7}}]})",
       "an index of refraction must be in [1e-6, 1e6] (is 1e+07)"},
      {sphere + R"("material": {"type": "dielectric", "ior": @1e-7}}]})",
       "an index of refraction must be in [1e-6, 1e6] (is 1e-07)"},
  };
  for (const BadScene& bad : cases) {
    expect_error(bad);
  }
  Scene scene;
  std::string error;
  EXPECT_TRUE(
      parse(sphere + "\"material\": {\"type\": \"dielectric\", \"ior\": 1e6}}]}", scene, error))
      << error;
}

TEST(Scene, LoadSceneReportsAMissingFile) {
  Scene scene;
  std::string error;
  EXPECT_FALSE(load_scene(scene_path("does-not-exist.json"), scene, error));
  EXPECT_NE(error.find("does-not-exist.json"), std::string::npos);
}

TEST(Scene, ExampleScenesLoad) {
  int count = 0;
  for (const auto& entry :
       fs::directory_iterator(fs::path(gfield::build_paths::data_dir()) / "scenes")) {
    if (entry.path().extension() != ".json")
      continue;
    Scene scene;
    std::string error;
    EXPECT_TRUE(load_scene(entry.path().string(), scene, error)) << error;
    EXPECT_FALSE(scene.purpose.empty()) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 6);
}

TEST(Texture, ColorChartAndChecker) {
  Material m;
  m.texture = TextureType::kColorChart;
  // Top-left patch "dark skin" (115, 82, 68) in the middle of its cell: u = 1/12, v = 1 - 1/8.
  const glm::vec3 dark_skin = texture_albedo(m, {1.0f / 12.0f, 1.0f - 1.0f / 8.0f});
  EXPECT_NEAR(dark_skin.r, srgb_to_linear(115.0f / 255.0f), 1e-6f);
  EXPECT_NEAR(dark_skin.g, srgb_to_linear(82.0f / 255.0f), 1e-6f);
  // Bottom-right patch "black" (52, 52, 52).
  EXPECT_NEAR(texture_albedo(m, {11.0f / 12.0f, 1.0f / 8.0f}).r, srgb_to_linear(52.0f / 255.0f),
              1e-6f);
  // Gaps between patches are near black.
  EXPECT_LT(texture_albedo(m, {1.0f / 6.0f, 0.5f}).r, 0.02f);
  m.texture = TextureType::kChecker;
  m.checker_scale = {4, 2};
  EXPECT_EQ(texture_albedo(m, {0.1f, 0.1f}), m.checker_colors[0]);
  EXPECT_EQ(texture_albedo(m, {0.3f, 0.1f}), m.checker_colors[1]);
  EXPECT_EQ(texture_albedo(m, {0.3f, 0.6f}), m.checker_colors[0]);
}

TEST(Environment, DirectionMappings) {
  // Equirectangular: -Z is the centre, +X three quarters, up is the top row.
  EXPECT_NEAR(equirect_uv({0, 0, -1}).x, 0.5f, 1e-6f);
  EXPECT_NEAR(equirect_uv({1, 0, 0}).x, 0.75f, 1e-6f);
  EXPECT_NEAR(equirect_uv({0, 1, 0}).y, 0.0f, 1e-6f);
  EXPECT_NEAR(equirect_uv({0, -1, 0}).y, 1.0f, 1e-6f);
  // Cube: the OpenGL table (face, s, t).
  const glm::vec3 px = cube_coords({1, 0.5f, -0.25f});
  EXPECT_EQ(px.z, 0.0f);
  EXPECT_NEAR(px.x, 0.5f * (0.25f + 1.0f), 1e-6f);  // sc = -rz
  EXPECT_NEAR(px.y, 0.5f * (-0.5f + 1.0f), 1e-6f);  // tc = -ry
  EXPECT_EQ(cube_coords({0, -2, 0.1f}).z, 3.0f);
  EXPECT_EQ(cube_coords({0.1f, 0, -3}).z, 5.0f);
}

TEST(Environment, EquirectImageLookupReturnsPixelValues) {
  Image image(8, 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x)
      image.at(x, y) = glm::vec3(float(x), float(y), 1.0f);
  }
  const std::string file = scene_path("scene_test_env.exr");
  std::string error;
  ASSERT_TRUE(save_image(file, image, error)) << error;
  EnvironmentDesc desc;
  desc.type = EnvironmentType::kEquirect;
  desc.file = file;
  desc.intensity = 2.0f;
  Environment env;
  ASSERT_TRUE(load_environment(desc, env, error)) << error;
  // The direction through the centre of pixel (5, 1): u = 5.5/8, v = 1.5/4.
  const float phi = (5.5f / 8.0f - 0.5f) * 2.0f * 3.14159265f;
  const float theta = 1.5f / 4.0f * 3.14159265f;
  const glm::vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta),
                    -std::sin(theta) * std::cos(phi));
  const glm::vec3 v = environment_radiance(env, d);
  EXPECT_NEAR(v.x, 10.0f, 1e-3f);
  EXPECT_NEAR(v.y, 2.0f, 1e-3f);
  EXPECT_NEAR(v.z, 2.0f, 1e-6f);
}

TEST(Environment, CubeFacesInOpenGlOrder) {
  EnvironmentDesc desc;
  desc.type = EnvironmentType::kCube;
  std::string error;
  for (size_t f = 0; f < 6; ++f) {
    desc.faces[f] = scene_path("scene_test_face" + std::to_string(f) + ".exr");
    ASSERT_TRUE(save_image(desc.faces[f], Image(4, 4, glm::vec3(float(f))), error)) << error;
  }
  Environment env;
  ASSERT_TRUE(load_environment(desc, env, error)) << error;
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(environment_radiance(env, axes[f]).x, float(f));
  }
  // Faces of different sizes are refused, naming the file.
  ASSERT_TRUE(save_image(desc.faces[3], Image(8, 8), error));
  EXPECT_FALSE(load_environment(desc, env, error));
  EXPECT_NE(error.find("scene_test_face3.exr"), std::string::npos) << error;
}

TEST(ImageIo, ReadsRadianceHdr) {
  const float pixels[2 * 1 * 3] = {0.5f, 2.0f, 8.0f, 0.125f, 0.25f, 1.0f};
  const std::string file = scene_path("scene_test_tiny.hdr");
  ASSERT_NE(stbi_write_hdr(file.c_str(), 2, 1, 3, pixels), 0);
  Image image;
  std::string error;
  ASSERT_TRUE(load_image(file, image, error)) << error;
  ASSERT_EQ(image.width, 2);
  EXPECT_EQ(image.at(0, 0), glm::vec3(0.5f, 2.0f, 8.0f));  // powers of two are exact in RGBE
  EXPECT_EQ(image.at(1, 0), glm::vec3(0.125f, 0.25f, 1.0f));
}

TEST(ImageIo, ReadsFlatPngsThatDeflateFarBelowThreeBytesAPixel) {
  // tests/core/data: all-black PNGs made with Python's zlib at level 9 (1-bit grey 4096^2 in
  // 2,116 bytes, 8-bit grey 1024^2 in 1,097 bytes), as a screen grab of a black window is.
  for (const char* name : {"black-1bit-4096.png", "black-8bit-1024.png"}) {
    Image image;
    std::string error;
    ASSERT_TRUE(load_image(std::string(gfield::build_paths::tests_dir()) + "/core/data/" + name,
                           image, error))
        << error;
    EXPECT_EQ(image.at(image.width - 1, image.height - 1), glm::vec3(0.0f)) << name;
  }
}

TEST(Environment, StudioHasStructure) {
  // Checkered floor below, brighter sky above, finite everywhere.
  EXPECT_NE(studio_environment_radiance(glm::normalize(glm::vec3(0.2f, -1, 0.2f))),
            studio_environment_radiance(glm::normalize(glm::vec3(1.2f, -1, 0.2f))));
  for (int i = 0; i < 200; ++i) {
    const float a = float(i) * 0.7f, b = float(i) * 0.31f;
    const glm::vec3 d(std::cos(a) * std::cos(b), std::sin(b), std::sin(a) * std::cos(b));
    const glm::vec3 v = studio_environment_radiance(d);
    EXPECT_TRUE(std::isfinite(v.x) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f);
  }
}

TEST(ImageIo, RoundTripsExrExactlyAndPngWithinQuantisation) {
  Image image(5, 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    image.pixels[i] = glm::vec3(float(i) / 15.0f, 0.25f, 1.0f - float(i) / 15.0f);
  }
  std::string error;
  Image back;
  ASSERT_TRUE(save_image(scene_path("scene_test_rt.exr"), image, error)) << error;
  ASSERT_TRUE(load_image(scene_path("scene_test_rt.exr"), back, error)) << error;
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  EXPECT_EQ(back.pixels, image.pixels);
  ASSERT_TRUE(save_image(scene_path("scene_test_rt.png"), image, error)) << error;
  ASSERT_TRUE(load_image(scene_path("scene_test_rt.png"), back, error)) << error;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(linear_to_srgb(back.pixels[i][c]), linear_to_srgb(image.pixels[i][c]),
                  0.5f / 255.0f + 1e-5f);
    }
  }
  EXPECT_FALSE(save_image(scene_path("scene_test_rt.bmp"), image, error));
  EXPECT_FALSE(load_image(scene_path("missing.exr"), back, error));
  EXPECT_NE(error.find("missing.exr"), std::string::npos);
}

}  // namespace
}  // namespace gfield
