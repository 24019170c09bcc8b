// Scenes of any extent and cameras of any field of view gfield-view renders: a unit
// object beside a floor of 1e6 is neither clipped (the depth range follows the objects, not the
// scene's extent) nor loses its shadow (ray offsets follow the hit's coordinates), fields of
// view up to 179.9 degrees and down to kMinViewFovDegrees match the reference tracer, and a
// narrower one is refused naming the file. Both tools run as commands: gfield render (the
// reference, strata centres) and gfield-view --headless at the same pixel centres.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "gfield/image.hpp"
#include "gfield/image_metrics.hpp"
#include "runtime/gpu_scene.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(gfield::build_paths::test_tmp()) / "extreme_view";

/// spot and a mirror sphere on a checkered floor `floor` units wide, seen with `fov` degrees.
std::string floor_scene(double floor, double fov) {
  std::ostringstream s;
  s << R"({"camera": {"position": [0, 1.2, 3.4], "target": [0, 0.2, 0], "fov": )" << fov
    << R"(},
  "image": {"width": 96, "height": 96}, "environment": {"type": "studio"}, "ambient": 0.3,
  "lights": [{"type": "directional", "direction": [-0.3, -1, -0.4], "intensity": 0.8}],
  "objects": [
    {"shape": "mesh", "file": ")" +
           std::string(gfield::build_paths::mesh_dir()) + R"(/spot.obj", "gimage": ")"
    << (kDir / "spot.gimage.exr").string() << R"(", "gfield": ")"
    << (kDir / "spot.gfield.exr").string() << R"(", "transform": {"translate": [0, 0.1, 0]},
     "material": {"type": "diffuse", "color": [0.8, 0.5, 0.3]}},
    {"shape": "sphere", "radius": 0.3, "transform": {"translate": [0.8, 0.3, 0.5]},
     "material": {"type": "mirror"}},
    {"shape": "quad", "size": [)"
    << floor << ", " << floor << R"(],
     "transform": {"rotate": [-90, 0, 0], "translate": [0, -0.63, 0]},
     "material": {"type": "diffuse", "texture": "checker", "scale": 20}}]})";
  return s.str();
}

/// A checkered unit quad seen from 10 units with `fov` degrees, 8 squares across the view.
std::string telephoto_scene(double fov) {
  const double width = 20.0 * std::tan(fov * 3.14159265358979 / 360.0);
  std::ostringstream s;
  s.precision(17);
  s << R"({"camera": {"position": [0.0013, 0.0021, 10], "target": [0.0013, 0.0021, 0], "fov": )"
    << fov << R"(}, "image": {"width": 96, "height": 96}, "environment": {"type": "studio"},
  "ambient": 0.5, "lights": [{"type": "directional", "direction": [-0.3, -0.2, -1], "intensity": 0.5}],
  "objects": [{"shape": "quad", "size": [1, 1],
    "material": {"type": "diffuse", "texture": "checker", "scale": )"
    << 8.0 / width << "}}]}";
  return s.str();
}

class ExtremeView : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fs::create_directories(kDir);
    const test::CliRun r =
        test::run_cli("build " + std::string(gfield::build_paths::mesh_dir()) + "/spot.obj -o " +
                      (kDir / "spot").string() + " --size 256 --samples 12 --verify-rays 0");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  /// PSNR of gfield-view against gfield render on `scene`.
  static double view_psnr(const std::string& name, const std::string& scene) {
    const std::string file = (kDir / (name + ".json")).string();
    std::ofstream(file) << scene;
    const std::string reference = (kDir / (name + "-reference.exr")).string();
    const std::string view = (kDir / (name + "-view.exr")).string();
    const test::CliRun a = test::run_cli(
        "render " + file + " --allow-outside-paths --spp 1 --strata-centres -q -o " + reference);
    EXPECT_EQ(a.exit_code, 0) << a.err;
    const test::CliRun b = test::run_program(gfield::build_paths::view(),
                                             file + " --allow-outside-paths --headless -o " + view);
    EXPECT_EQ(b.exit_code, 0) << b.err;
    Image x, y;
    std::string error;
    if (!load_image(reference, x, error) || !load_image(view, y, error)) {
      ADD_FAILURE() << error;
      return 0.0;
    }
    return compare_images(clamped(y), clamped(x)).psnr;
  }
  static Image clamped(Image image) {
    for (glm::vec3& p : image.pixels)
      p = glm::clamp(p, 0.0f, 1.0f);
    return image;
  }
};

TEST_F(ExtremeView, AUnitObjectBesideAFloorOfAnyExtentRendersLikeTheReference) {
  // A near plane at a fixed fraction of the scene's extent would clip spot and the sphere.
  for (double floor : {10.0, 1e4, 1e6})
    EXPECT_GT(view_psnr("floor", floor_scene(floor, 40.0)), 38.0) << floor;
}

TEST_F(ExtremeView, FieldsOfViewFromTheNarrowestToTheWidestRenderLikeTheReference) {
  // A near plane fitted to the view's axis alone would clip the edges of the widest views.
  for (double fov : {179.0, 179.9})
    EXPECT_GT(view_psnr("wide", floor_scene(10.0, fov)), 38.0) << fov;
  EXPECT_GT(view_psnr("narrow", telephoto_scene(kMinViewFovDegrees)), 38.0);
}

TEST_F(ExtremeView, AFieldOfViewNarrowerThanFloatResolvesIsRefusedNamingTheFile) {
  const std::string file = (kDir / "too-narrow.json").string();
  std::ofstream(file) << telephoto_scene(1e-9);
  const std::string out = (kDir / "too-narrow.png").string();
  fs::remove(out);
  const test::CliRun r =
      test::run_program(gfield::build_paths::view(), file + " --headless -o " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(file + ": /camera/fov: the camera's field of view of 1e-09 degrees"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));
  const test::CliRun reference =
      test::run_cli("render " + file + " --spp 1 -q -o " + out + ".reference.png");
  EXPECT_EQ(reference.exit_code, 0)
      << "the reference tracer renders any field of view: " << reference.err;
}

}  // namespace
}  // namespace gfield
