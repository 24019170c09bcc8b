// The field method's two tracing passes: the compute dispatch and the fragment pass draw the
// same picture, bit for bit, with the same work, on the example scenes (mirrors, a textured
// mirror, glass; fields and BVHs); a scene past the objects whose order keys a ray keeps draws
// what a scene within them draws; and --pass auto's trial times both and keeps the faster.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "geometry/scene_file.hpp"
#include "runtime/methods/geometry_field.hpp"
#include "runtime/methods/trace_pass.hpp"
#include "runtime/shader_program.hpp"
#include "runtime/work_counters.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/example_scene.hpp"
#include "test_support/gl_suite.hpp"

namespace gfield {
namespace {
namespace fs = std::filesystem;

const fs::path kDir = fs::path(gfield::build_paths::test_tmp()) / "runtime_trace_pass";

TEST(PassTrial, AlternatesFromComputeThenKeepsTheFasterTimedFrame) {
  PassTrial trial;
  restart_pass_trial(trial, "program at 64x64");
  // Warm-ups (first of each pass) are slow and left out; compute's best timed frame is 5 ms.
  const double frames[] = {900.0, 800.0, 6.0, 7.0, 5.0, 6.5};
  const TracePass C = TracePass::kCompute, F = TracePass::kFragment;
  const TracePass expected[] = {C, F, C, F, C, F};
  for (int k = 0; k < 6; ++k) {
    EXPECT_FALSE(pass_trial_done(trial));
    const TracePass pass = next_trace_pass(trial);
    EXPECT_EQ(pass, expected[k]) << "frame " << k;
    record_trace_pass(trial, pass, frames[k]);
  }
  ASSERT_TRUE(pass_trial_done(trial));
  EXPECT_EQ(next_trace_pass(trial), TracePass::kCompute);
  EXPECT_EQ(describe_pass_trial(trial), "compute (auto: 5.0 ms against fragment 6.5 ms)");
  record_trace_pass(trial, TracePass::kFragment, 1.0);  // a trial once done takes no more
  EXPECT_EQ(next_trace_pass(trial), TracePass::kCompute);
}

TEST(PassTrial, PicksTheFragmentPassWhenItIsFasterAndRestartsForANewKey) {
  PassTrial trial;
  restart_pass_trial(trial, "a");
  for (int k = 0; k < 1 + kPassTrialFrames; ++k) {
    record_trace_pass(trial, TracePass::kCompute, 10.0);
    record_trace_pass(trial, TracePass::kFragment, 8.0);
  }
  EXPECT_EQ(next_trace_pass(trial), TracePass::kFragment);
  EXPECT_EQ(describe_pass_trial(trial), "fragment (auto: 8.0 ms against compute 10.0 ms)");
  restart_pass_trial(trial, "a");
  EXPECT_TRUE(pass_trial_done(trial));
  restart_pass_trial(trial, "b");
  EXPECT_FALSE(pass_trial_done(trial));
  EXPECT_EQ(describe_pass_trial(trial), "compute (auto: measuring)");
}

TEST(PassTrial, APassWhoseProgramDoesNotBuildLosesAndIsNamed) {
  PassTrial trial;
  restart_pass_trial(trial, "a");
  const double inf = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 1 + kPassTrialFrames; ++k) {
    record_trace_pass(trial, TracePass::kCompute, inf);
    record_trace_pass(trial, TracePass::kFragment, 90.0);
  }
  EXPECT_EQ(next_trace_pass(trial), TracePass::kFragment);
  EXPECT_EQ(describe_pass_trial(trial), "fragment (auto: compute did not build)");
}

class TracePassTest : public test::GlSuite {};

struct PassFrame {
  Image image;
  FrameStats stats;
};

PassFrame render_in(GeometryFieldMethod& method, const Scene& scene, TracePass pass, int width,
                    int height) {
  method.settings().pass = pass;
  PassFrame frame;
  frame.image = render_image(method, scene.camera, width, height, 1, &frame.stats);
  return frame;
}

/// Pixels where the two pictures differ at all (every pixel when their sizes differ).
size_t differing_pixels(const Image& a, const Image& b) {
  if (a.pixels.size() != b.pixels.size())
    return std::max(a.pixels.size(), b.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    differing += a.pixels[i] != b.pixels[i] ? 1 : 0;
  return differing;
}

/// Example scene `name` loaded into `method` (assets built into the test folder).
void load_example(const std::string& name, Scene& scene, GpuScene& gpu,
                  GeometryFieldMethod& method) {
  fs::create_directories(kDir);
  const fs::path file = kDir / (name + ".json");
  std::ofstream(file) << test::example_scene(name, kDir / "examples");
  std::string error;
  std::vector<std::string> warnings;
  ASSERT_TRUE(load_scene_file(file.string(), scene, warnings, error, OutsidePaths::kAllowed) &&
              gpu.load(scene, error) && method.load(gpu, default_shader_dir(), error))
      << error;
}

TEST_F(TracePassTest, ComputeAndFragmentPassesDrawTheSamePictureWithTheSameWork) {
  // Odd sizes leave part-filled work groups at the frame's edges.
  constexpr int kSize = 83;
  for (const char* name :
       {"mirror-torus-instances", "textured-mirror", "davis-wyman-color-chart"}) {
    SCOPED_TRACE(name);
    Scene scene;
    GpuScene gpu;
    GeometryFieldMethod method;
    ASSERT_NO_FATAL_FAILURE(load_example(name, scene, gpu, method));
    method.settings().max_depth = 4;
    method.settings().count_work = true;
    for (MeshIntersection intersect : {MeshIntersection::kField, MeshIntersection::kBvh}) {
      method.settings().intersect = intersect;
      const PassFrame compute = render_in(method, scene, TracePass::kCompute, kSize, kSize);
      const PassFrame fragment = render_in(method, scene, TracePass::kFragment, kSize, kSize);
      ASSERT_EQ(compute.image.pixels.size(), size_t(kSize * kSize));
      EXPECT_EQ(differing_pixels(compute.image, fragment.image), 0u);
      double lit = 0.0;
      for (const glm::vec3& p : compute.image.pixels)
        lit += p.r + p.g + p.b > 0.0f ? 1.0 : 0.0;
      EXPECT_GT(lit, 0.9 * kSize * kSize) << "the compute pass drew the frame";
      EXPECT_GT(compute.stats.count("secondary rays"), 0.0);
      for (const auto& [count, value] : fragment.stats.counts)
        EXPECT_EQ(compute.stats.count(count), value) << count;
      const char* work = intersect == MeshIntersection::kField ? "field lookups" : "BVH traversals";
      EXPECT_GT(compute.stats.count(work), 0.0) << work;
    }
  }
}

TEST_F(TracePassTest, ComputeTilesCoverAOneTileFrameAndMoreGroupsThanOneDimensionHolds) {
  Scene scene;
  GpuScene gpu;
  GeometryFieldMethod method;
  ASSERT_NO_FATAL_FAILURE(load_example("mirror-torus-instances", scene, gpu, method));
  method.settings().max_depth = 0;  // the G-buffer's hits shaded, shadows traced
  // 5x5: one tile, part-filled; 2048x1040: 256 x 130 tiles, over the 2^15 groups a dispatch
  // puts in x, so the groups spread into y. That frame looks up, 45 degrees above the
  // horizon, at the studio's sky alone (the torus and the spots lie below the camera): every
  // pixel its own direction, in a frame that costs seconds, not a minute, on llvmpipe.
  struct Frame {
    int width;
    int height;
    glm::vec3 target;  ///< where the camera looks
  };
  const glm::vec3 sky = scene.camera.position + glm::vec3(0.0f, 1.0f, -1.0f);
  for (const auto& [width, height, target] :
       {Frame{5, 5, scene.camera.target}, Frame{2048, 1040, sky}}) {
    SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
    scene.camera.target = target;
    const PassFrame compute = render_in(method, scene, TracePass::kCompute, width, height);
    const PassFrame fragment = render_in(method, scene, TracePass::kFragment, width, height);
    ASSERT_EQ(compute.image.pixels.size(), size_t(width) * size_t(height));
    EXPECT_EQ(differing_pixels(compute.image, fragment.image), 0u);
  }
}

TEST_F(TracePassTest, ScenesPastTheCachedEntriesDrawWhatTheCachedOnesDraw) {
  // trace_scene computes the objects' order keys once per ray in a scene of at most
  // SCENE_CACHED_ENTRIES objects (GF_CACHED_ENTRIES) and once per pass in a larger one. The
  // larger scene here is mirror-torus-instances after small spheres deep inside its diffuse
  // spots, where no ray reaches, so that its own objects lie past the cached ones: the same
  // picture, bit for bit, by fields and by BVHs.
  constexpr int kSize = 83;
  Scene scene;
  GpuScene gpu;
  GeometryFieldMethod method;
  ASSERT_NO_FATAL_FAILURE(load_example("mirror-torus-instances", scene, gpu, method));
  ASSERT_LE(scene.objects.size(), size_t(gpu::SCENE_CACHED_ENTRIES));
  Scene larger = scene;
  larger.objects.clear();
  std::vector<SceneObject> spots;
  for (const SceneObject& o : scene.objects)
    if (o.shape.type == ShapeType::kMesh && o.material.type == MaterialType::kDiffuse)
      spots.push_back(o);
  ASSERT_FALSE(spots.empty());
  for (size_t k = 0; k + scene.objects.size() <= size_t(gpu::SCENE_CACHED_ENTRIES); ++k) {
    SceneObject sphere;
    sphere.name = "hidden " + std::to_string(k);
    sphere.shape.radius = 0.01f;  // spot's surface lies 0.05 or more from its mesh's origin
    sphere.transform.translate = spots[k % spots.size()].transform.translate;
    larger.objects.push_back(sphere);
  }
  larger.objects.insert(larger.objects.end(), scene.objects.begin(), scene.objects.end());
  GpuScene larger_gpu;
  GeometryFieldMethod larger_method;
  std::string error;
  ASSERT_TRUE(larger_gpu.load(larger, error) &&
              larger_method.load(larger_gpu, default_shader_dir(), error))
      << error;
  for (MeshIntersection intersect : {MeshIntersection::kField, MeshIntersection::kBvh}) {
    for (GeometryFieldMethod* m : {&method, &larger_method}) {
      m->settings().max_depth = 4;
      m->settings().intersect = intersect;
    }
    const PassFrame cached = render_in(method, scene, TracePass::kFragment, kSize, kSize);
    const PassFrame per_pass = render_in(larger_method, larger, TracePass::kFragment, kSize, kSize);
    ASSERT_EQ(cached.image.pixels.size(), size_t(kSize * kSize));
    EXPECT_EQ(differing_pixels(cached.image, per_pass.image), 0u)
        << (intersect == MeshIntersection::kField ? "field" : "BVH");
  }
}

TEST_F(TracePassTest, AutoTimesBothPassesOnItsFirstFramesAndSaysWhichItKept) {
  Scene scene;
  GpuScene gpu;
  GeometryFieldMethod method;
  ASSERT_NO_FATAL_FAILURE(load_example("mirror-torus-instances", scene, gpu, method));
  ASSERT_EQ(method.settings().pass, TracePass::kAuto);
  EXPECT_NE(method.status().find("tracing pass: compute (auto: measuring)"), std::string::npos)
      << method.status();
  for (int k = 0; k < 2 * (1 + kPassTrialFrames); ++k)
    render_image(method, scene.camera, 32, 32, 1);
  const std::string status = method.status();
  EXPECT_NE(status.find(" ms against "), std::string::npos) << status;
  // The counting build's frame (the benchmarks draw one between timed ones) shares the trial.
  method.settings().count_work = true;
  render_image(method, scene.camera, 32, 32, 1);
  EXPECT_TRUE(method.pass_settled()) << method.status();
  method.settings().count_work = false;
  // A new frame size is another trial.
  render_image(method, scene.camera, 40, 40, 1);
  EXPECT_NE(method.status().find("(auto: measuring)"), std::string::npos) << method.status();
}

}  // namespace
}  // namespace gfield
