// The one method architecture (runtime/method.hpp, method_registry.hpp, view_session.hpp)
// driven headless as the viewer drives it: every registered method of one scene is switched to
// live in one session, objects move without re-uploading the assets, a second method fills the
// right half, and the command line's method list and options come from the registry.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "gfield/exr_io.hpp"
#include "gfield/gpu_storage.hpp"
#include "gfield/image_metrics.hpp"
#include "runtime/asset_memory.hpp"
#include "runtime/method_registry.hpp"
#include "runtime/shader_program.hpp"
#include "runtime/view_session.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/gl_suite.hpp"

namespace gfield {
namespace {
namespace fs = std::filesystem;

const fs::path kDir = fs::path(gfield::build_paths::test_tmp()) / "view_session";
constexpr int kSize = 64;

/// A scene every method can draw: diffuse spot (assets built at set-up), one glass slab (the
/// glass method's glass, no mirrors), a checker floor and a directional light.
std::string session_scene() {
  const std::string asset = (kDir / "spot").string();
  return R"({"camera": {"position": [0, 1.2, 3.4], "target": [0, 0.2, 0], "fov": 40},
  "image": {"width": 64, "height": 64}, "environment": {"type": "studio"}, "ambient": 0.2,
  "lights": [{"type": "directional", "direction": [-0.3, -1, -0.4], "intensity": 1.2}],
  "objects": [
    {"name": "spot", "shape": "mesh", "file": ")" +
         std::string(gfield::build_paths::mesh_dir()) + R"(/spot.obj",
     "gimage": ")" +
         asset + R"(.gimage.exr", "gfield": ")" + asset + R"(.gfield.exr",
     "transform": {"translate": [0, 0, -0.6]}, "material": {"type": "diffuse",
     "color": [0.8, 0.5, 0.3]}},
    {"name": "glass", "shape": "slab", "size": [1.6, 1.2], "thickness": 0.15,
     "transform": {"translate": [0.2, 0.3, 0.6], "rotate": [0, 20, 0]},
     "material": {"type": "dielectric", "ior": 1.5}},
    {"name": "floor", "shape": "quad", "size": [6, 6],
     "transform": {"rotate": [-90, 0, 0], "translate": [0, -0.6, 0]},
     "material": {"type": "diffuse", "texture": "checker", "scale": 12}}]})";
}

class ViewSessionTest : public test::GlSuite {
 protected:
  static void SetUpTestSuite() {
    ASSERT_TRUE(make_context());
    fs::create_directories(kDir);
    const test::CliRun run =
        test::run_cli("build " + std::string(gfield::build_paths::mesh_dir()) + "/spot.obj -o " +
                      (kDir / "spot").string() + " --size 128 --samples 8 --verify-rays 0");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::ofstream(kDir / "scene.json") << session_scene();
    ready_ = true;
  }
};

/// Finite everywhere and not one flat colour: the method drew something.
bool drew_something(const Image& image) {
  float lo = 1e30f, hi = -1e30f;
  for (const glm::vec3& p : image.pixels) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return false;
    lo = std::min(lo, p.y);
    hi = std::max(hi, p.y);
  }
  return hi - lo > 0.05f;
}

TEST(MethodRegistry, NamesAreUniqueAndEachMethodCarriesItsName) {
  std::set<std::string> names;
  for (const MethodEntry& entry : method_registry()) {
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name;
    const std::unique_ptr<Method> method = entry.make();
    ASSERT_NE(method, nullptr);
    EXPECT_EQ(method->info().name, entry.name);
    EXPECT_NE(make_method(entry.name), nullptr);
    for (const MethodOption& o : method->options())
      EXPECT_FALSE(o.name.empty() || o.help.empty() || o.label.empty()) << entry.name;
  }
  for (const char* name : {"field", "cubemap", "envmap", "wyman2005", "davis-wyman", "glass"})
    EXPECT_TRUE(names.count(name)) << name;
  EXPECT_EQ(make_method("no-such-method"), nullptr);
}

TEST(MethodRegistry, HelpListsEveryMethodAndItsOptions) {
  const test::CliRun help = test::run_program(gfield::build_paths::view(), "--help");
  ASSERT_EQ(help.exit_code, 0) << help.err;
  for (const MethodEntry& entry : method_registry()) {
    EXPECT_NE(help.out.find(entry.name), std::string::npos) << entry.name;
    for (const MethodOption& o : entry.make()->options())
      EXPECT_NE(help.out.find("--" + o.name), std::string::npos) << o.name;
  }
  const test::CliRun bad =
      test::run_program(gfield::build_paths::view(), "scene.json --method no-such");
  EXPECT_NE(bad.exit_code, 0);
}

TEST_F(ViewSessionTest, SwitchesBetweenEveryMethodLiveAndMovesObjectsWithoutReupload) {
  Scene scene;
  std::string error;
  ASSERT_TRUE(load_scene((kDir / "scene.json").string(), scene, error, OutsidePaths::kAllowed))
      << error;
  ViewSession session;
  ASSERT_TRUE(session.load(scene, default_shader_dir(), error)) << error;
  Framebuffer frame;
  ASSERT_TRUE(frame.resize(kSize, kSize));
  std::vector<Image> pictures;
  for (int k = 0; k < session.method_count(); ++k) {
    SCOPED_TRACE(session.method(k).info().name);
    ASSERT_TRUE(session.select(k, error)) << error;
    session.draw(scene.camera, frame);
    pictures.push_back(frame.read_image());
    EXPECT_TRUE(drew_something(pictures.back()));
  }
  // Back to the first method: the same picture as before (nothing of the others leaked).
  ASSERT_TRUE(session.select(0, error)) << error;
  session.draw(scene.camera, frame);
  EXPECT_EQ(frame.read_image().pixels, pictures[0].pixels);
  // The methods are not one picture under six names.
  EXPECT_LT(compare_images(pictures[0], pictures.back()).psnr, 60.0);

  // Move spot: the buffers are refilled, no texture array is uploaded again, every method
  // draws the moved scene.
  const int uploads = session.scene().assets().texture_uploads();
  EXPECT_GE(uploads, 2);  // geometry images and fields
  session.scene().scene().objects[0].transform.translate.x += 0.4f;
  session.scene_changed();
  for (int k = 0; k < session.method_count(); ++k) {
    SCOPED_TRACE(session.method(k).info().name);
    ASSERT_TRUE(session.select(k, error)) << error;
    session.draw(scene.camera, frame);
    EXPECT_NE(frame.read_image().pixels, pictures[size_t(k)].pixels);
  }
  EXPECT_EQ(session.scene().assets().texture_uploads(), uploads);
}

TEST_F(ViewSessionTest, SecondMethodFillsTheRightHalf) {
  Scene scene;
  std::string error;
  ASSERT_TRUE(load_scene((kDir / "scene.json").string(), scene, error, OutsidePaths::kAllowed))
      << error;
  ViewSession session;
  ASSERT_TRUE(session.load(scene, default_shader_dir(), error)) << error;
  const int field = session.find("field"), glass = session.find("glass");
  ASSERT_GE(field, 0);
  ASSERT_GE(glass, 0);
  Framebuffer frame;
  ASSERT_TRUE(frame.resize(kSize, kSize));
  ASSERT_TRUE(session.select(glass, error)) << error;
  session.draw(scene.camera, frame);
  const Image glass_picture = frame.read_image();
  ASSERT_TRUE(session.select(field, error)) << error;
  session.draw(scene.camera, frame);
  const Image field_picture = frame.read_image();
  ASSERT_TRUE(session.select_compare(glass, error)) << error;
  session.draw(scene.camera, frame);
  const Image both = frame.read_image();
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const Image& expected = x < kSize / 2 ? field_picture : glass_picture;
      ASSERT_EQ(both.at(x, y), expected.at(x, y)) << x << "," << y;
    }
  }
}

TEST_F(ViewSessionTest, AssetMemoryNamesEachMeshsGpuBytes) {
  Scene scene;
  std::string error;
  ASSERT_TRUE(load_scene((kDir / "scene.json").string(), scene, error, OutsidePaths::kAllowed))
      << error;
  ViewSession session;
  ASSERT_TRUE(session.load(scene, default_shader_dir(), error)) << error;
  ASSERT_TRUE(session.select(session.find("field"), error)) << error;
  GeometryField field;
  ASSERT_TRUE(load_geometry_field((kDir / "spot.gfield.exr").string(), field, error)) << error;
  char expected[160];
  std::snprintf(expected, sizeof(expected),
                "spot.obj: image %.1f MB, field RG8 + line table %.1f MB (up to %d hits a line)\n",
                double(geometry_image_gpu_bytes(128)) / 1e6,
                double(field_gpu_bytes(field, 8)) / 1e6, field.layers);
  EXPECT_EQ(asset_memory_lines(scene, session.scene().assets()), expected);
}

}  // namespace
}  // namespace gfield
