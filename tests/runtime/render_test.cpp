// Headless renders of the geometry-field method against the reference ray tracer (the library
// behind `gfield render`), same scene, same depth, same sample positions (strata centres):
// PSNR thresholds per scene, and refined > linear > nearest on every scene. Assets are built at
// test time with `gfield build` on a bundled mesh (small N to stay fast).

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "geometry/scene_file.hpp"
#include "gfield/image_metrics.hpp"
#include "gfield/scene.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/methods/geometry_field.hpp"
#include "runtime/shader_program.hpp"
#include "runtime/work_counters.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/example_scene.hpp"
#include "test_support/gl_suite.hpp"

namespace gfield {
namespace {
namespace fs = std::filesystem;

const fs::path kDir = fs::path(gfield::build_paths::test_tmp()) / "runtime_render";
constexpr int kSize = 128;
constexpr int kSamples = 4;  // per pixel, both renderers, at the same positions

/// The mesh object of the test scenes: spot, geometry image and field built by `gfield build`.
std::string spot_object(const std::string& name, const std::string& transform,
                        const std::string& material) {
  const fs::path asset = kDir / "spot";
  return R"({"name": ")" + name + R"(", "shape": "mesh", "file": ")" +
         std::string(gfield::build_paths::mesh_dir()) + R"(/spot.obj", "gimage": ")" +
         asset.string() + R"(.gimage.exr", "gfield": ")" + asset.string() +
         R"(.gfield.exr", "transform": )" + transform + R"(, "material": )" + material + "}";
}

std::string scene_text(const std::string& objects, const std::string& camera) {
  return R"({"camera": )" + camera + R"(, "image": {"width": 128, "height": 128},
  "environment": {"type": "studio"}, "ambient": [0.1, 0.1, 0.1],
  "lights": [{"type": "directional", "direction": [-0.3, -1, -0.4], "intensity": 1.5}],
  "objects": [{"name": "floor", "shape": "quad", "size": [6, 6],
               "transform": {"rotate": [-90, 0, 0], "translate": [0, -0.6, 0]},
               "material": {"type": "diffuse", "texture": "checker", "scale": 12}}, )" +
         objects + "]}";
}

const char* kCamera = R"({"position": [0, 1.2, 3.2], "target": [0, 0.3, 0], "fov": 40})";

/// min_psnr: the refined mode's PSNR measured on llvmpipe minus a margin (docs/runtime.md);
/// linear_beats_nearest: whether the paper's linear kernel measured better than nearest here.
struct TestScene {
  const char* name;
  std::string text;
  double min_psnr;
  bool linear_beats_nearest;
};

std::vector<TestScene> test_scenes() {
  return {
      {"mirror",
       scene_text(
           spot_object("mirror spot", R"({"translate": [-0.45, 0, 0], "rotate": [0, 30, 0]})",
                       R"({"type": "mirror", "tint": [0.9, 0.9, 0.9]})") +
               ", " +
               spot_object("red spot",
                           R"({"translate": [0.6, 0, -0.4], "rotate": [0, -60, 0], "scale": 0.8})",
                           R"({"type": "diffuse", "color": [0.8, 0.2, 0.15]})") +
               R"(, {"name": "ball", "shape": "sphere", "radius": 0.3,
                           "transform": {"translate": [0.5, -0.3, 0.6]},
                           "material": {"type": "mirror", "tint": [0.8, 0.85, 1.0]}})",
           kCamera),
       35.0, true},
      {"mirror-spheres",
       scene_text(R"({"name": "left", "shape": "sphere", "radius": 0.5,
                      "transform": {"translate": [-0.55, 0, 0]},
                      "material": {"type": "mirror", "tint": [1.0, 0.6, 0.6]}},
                     {"name": "right", "shape": "sphere", "radius": 0.5,
                      "transform": {"translate": [0.55, 0, 0]},
                      "material": {"type": "mirror", "tint": [0.6, 0.6, 1.0]}}, )" +
                      spot_object("spot", R"({"translate": [0, 0.1, -1.2], "rotate": [0, 20, 0]})",
                                  R"({"type": "diffuse", "color": [0.9, 0.8, 0.3]})"),
                  kCamera),
       48.5, true},
      {"refraction",
       scene_text(spot_object("glass spot", R"({"translate": [0, 0, 0.3], "rotate": [0, 40, 0]})",
                              R"({"type": "dielectric", "ior": "crown-glass"})") +
                      R"(, {"name": "chart", "shape": "quad", "size": [2.4, 1.6],
                           "transform": {"translate": [0, 0.3, -1.0]},
                           "material": {"type": "diffuse", "texture": "color-chart"}})",
                  kCamera),
       21.0, true},
  };
}

class RenderTest : public test::GlSuite {
 protected:
  static void SetUpTestSuite() {
    ASSERT_TRUE(make_context());
    fs::create_directories(kDir);
    const std::string command = std::string("\"") + gfield::build_paths::cli() + "\" build \"" +
                                std::string(gfield::build_paths::mesh_dir()) + "/spot.obj\" -o \"" +
                                (kDir / "spot").string() +
                                "\" --size 256 --samples 12 --method square --verify-rays 0 "
                                "> \"" +
                                (kDir / "build.log").string() + "\" 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    ready_ = true;
  }
};

/// PSNR (nearest, linear, refined; clamped pictures) of the geometry-field renderer against the
/// reference tracer on the scene `text` (written to kDir/NAME.json), both at size^2 with `spp`
/// samples at the same strata centres and the same depth. Writes NAME-refined.png and
/// NAME-reference.png beside it. False (with a failure recorded) when the scene does not load.
bool psnr_per_mode(const std::string& name, const std::string& text, int size, int spp, int depth,
                   double psnr[3], Scene& scene) {
  const fs::path file = kDir / (name + ".json");
  std::ofstream(file) << text;
  std::string error;
  std::vector<std::string> warnings;
  // The scenes name spot in data/meshes by absolute path.
  if (!load_scene_file(file.string(), scene, warnings, error, OutsidePaths::kAllowed)) {
    ADD_FAILURE() << error;
    return false;
  }
  ReferenceTracer tracer;
  GpuScene gpu;
  GeometryFieldMethod field;
  if (!tracer.build(scene, error) || !gpu.load(scene, error) ||
      !field.load(gpu, default_shader_dir(), error)) {
    ADD_FAILURE() << error;
    return false;
  }
  RenderOptions options;
  options.width = options.height = size;
  options.samples_per_pixel = spp;
  options.max_depth = depth;
  options.jitter = false;
  const Image reference = clamped_to_display(tracer.render(options));
  save_image((kDir / (name + "-reference.png")).string(), reference, error);
  for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
    field.settings().mode = mode;
    field.settings().max_depth = depth;
    const Image image = clamped_to_display(render_image(field, scene.camera, size, size, spp));
    psnr[int(mode)] = compare_images(image, reference).psnr;
    std::printf("%s %s: PSNR %.2f dB\n", name.c_str(), lookup_mode_name(mode), psnr[int(mode)]);
    if (mode == LookupMode::kRefined)
      save_image((kDir / (name + "-refined.png")).string(), image, error);
  }
  return true;
}

TEST_F(RenderTest, MatchesReferenceTracerAndRefinedBeatsLinearBeatsNearest) {
  constexpr int kDepth = 6;
  for (const TestScene& test : test_scenes()) {
    SCOPED_TRACE(test.name);
    Scene scene;
    double psnr[3] = {0.0, 0.0, 0.0};
    if (!psnr_per_mode(test.name, test.text, kSize, kSamples, kDepth, psnr, scene))
      continue;
    EXPECT_GE(psnr[2], test.min_psnr);
    EXPECT_GT(psnr[2], psnr[1]);
    EXPECT_GT(psnr[2], psnr[0]);
    if (test.linear_beats_nearest) {
      EXPECT_GT(psnr[1], psnr[0]);
    }
  }
}

TEST_F(RenderTest, ExampleScenesMatchReferenceTracer) {
  // The issue's setting: 256^2, depth 4, default assets; 4 samples per pixel at the same strata
  // centres in both renderers (at 1 spp the refraction's chaotic pixels dominate: 22.8 dB).
  constexpr int kDepth = 4, kExampleSize = 256, kExampleSamples = 4;
  // Refined-mode PSNR measured on llvmpipe minus a margin (docs/results.md prints today's).
  // two-mirror-spheres has no mesh objects: no field lookups, the three modes are the same picture.
  const std::pair<const char*, double> scenes[] = {{"mirror-torus-instances", 43.5},
                                                   {"two-mirror-spheres", 53.5},
                                                   {"davis-wyman-color-chart", 33.5},
                                                   {"textured-mirror", 42.5}};
  for (const auto& [name, min_psnr] : scenes) {
    SCOPED_TRACE(name);
    Scene scene;
    double psnr[3] = {0.0, 0.0, 0.0};
    if (!psnr_per_mode(name, test::example_scene(name, kDir / "examples"), kExampleSize,
                       kExampleSamples, kDepth, psnr, scene))
      continue;
    EXPECT_GE(psnr[2], min_psnr);
    const bool has_fields =
        std::any_of(scene.objects.begin(), scene.objects.end(),
                    [](const SceneObject& o) { return o.shape.type == ShapeType::kMesh; });
    if (has_fields) {
      EXPECT_GT(psnr[2], psnr[1] + 1.0);
      EXPECT_GT(psnr[1], psnr[0]);
    } else {
      EXPECT_EQ(psnr[2], psnr[1]);
      EXPECT_EQ(psnr[1], psnr[0]);
    }
  }
}

/// The work of one frame of test scene `test` at 64^2, depth 4, 1 spp: per counter of
/// work_counters.hpp, for the refined field lookups and for the BVH.
nlohmann::json work_of_scene(const TestScene& test) {
  const fs::path file = kDir / (std::string("work-") + test.name + ".json");
  std::ofstream(file) << test.text;
  Scene scene;
  std::string error;
  std::vector<std::string> warnings;
  GpuScene gpu;
  GeometryFieldMethod field;
  if (!load_scene_file(file.string(), scene, warnings, error, OutsidePaths::kAllowed) ||
      !gpu.load(scene, error) || !field.load(gpu, default_shader_dir(), error)) {
    ADD_FAILURE() << error;
    return {};
  }
  nlohmann::json work;
  field.settings().max_depth = 4;
  field.settings().count_work = true;
  for (MeshIntersection intersect : {MeshIntersection::kField, MeshIntersection::kBvh}) {
    field.settings().intersect = intersect;
    FrameStats stats;
    render_image(field, scene.camera, 64, 64, 1, &stats);
    nlohmann::json& counts = work[intersect == MeshIntersection::kBvh ? "bvh" : "field"];
    for (int k = 0; k < gpu::WORK_COUNT; ++k)
      counts[work_count_name(k)] = stats.count(work_count_name(k));
  }
  return work;
}

TEST_F(RenderTest, WorkPerFrameStaysWithinItsCommittedBaseline) {
  // A guard that counts work, not time: texel fetches, Newton steps and BVH nodes are the same on
  // any device. The mirror scene and the refraction (glass) scene; a rise over 10% fails; after a
  // change that is meant to do more (or less) work, GFIELD_WRITE_WORK_BASELINES=1 rewrites the
  // baseline file, to be committed.
  const fs::path baselines =
      fs::path(gfield::build_paths::tests_dir()) / "runtime" / "work_baselines.json";
  nlohmann::json work;
  for (const TestScene& test : test_scenes()) {
    if (std::string(test.name) == "mirror" || std::string(test.name) == "refraction")
      work[test.name] = work_of_scene(test);
  }
  if (const char* write = std::getenv("GFIELD_WRITE_WORK_BASELINES"); write && *write == '1') {
    std::ofstream(baselines) << work.dump(2) << "\n";
    GTEST_SKIP() << "wrote " << baselines;
  }
  const nlohmann::json baseline = nlohmann::json::parse(std::ifstream(baselines));
  ASSERT_EQ(baseline.size(), 2u);
  for (const auto& [scene, by_intersect] : baseline.items()) {
    for (const auto& [intersect, counts] : by_intersect.items()) {
      for (const auto& [name, count] : counts.items()) {
        const double now = work[scene][intersect][name].get<double>();
        std::printf("%s %s %s: %.0f (baseline %.0f)\n", scene.c_str(), intersect.c_str(),
                    name.c_str(), now, count.get<double>());
        EXPECT_LE(now, 1.1 * count.get<double>()) << scene << " " << intersect << " " << name;
      }
    }
    EXPECT_GT(work[scene]["field"]["field lookups"].get<double>(), 0.0) << scene;
    EXPECT_GT(work[scene]["bvh"]["BVH nodes"].get<double>(), 0.0) << scene;
    EXPECT_EQ(work[scene]["bvh"]["field lookups"].get<double>(), 0.0) << scene;
  }
  for (const char* scene : {"mirror", "refraction"}) {
    const nlohmann::json& f = work[scene]["field"];
    const double lookups = f["field lookups"].get<double>();
    std::printf("%s: %.1f field + %.1f image fetches, %.2f Newton steps per lookup\n", scene,
                f["field texel fetches"].get<double>() / lookups,
                f["image texel fetches"].get<double>() / lookups,
                f["Newton steps"].get<double>() / lookups);
  }
}

}  // namespace
}  // namespace gfield
