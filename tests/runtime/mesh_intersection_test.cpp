// The geometry-field method's two ways of meeting meshes: looked up in their geometry
// fields, or traced exactly through a BVH of their triangles (--intersect bvh), which also traces
// the meshes that have no field. The BVH renders every example scene with meshes as well as the
// reference tracer itself can at one sample per pixel: against the reference's converged picture
// (16 samples per pixel, the truth a picture of this size approximates), the BVH's picture (pixel
// centres) is within 0.5 dB of the reference tracer's own picture of pixel centres, its picture
// quality bound. (Against the reference's pixel centres directly, a handful of grazing pixels in
// which float and double part ways cost 4 dB each at 64^2.)

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "geometry/scene_file.hpp"
#include "gfield/image_metrics.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/methods/geometry_field.hpp"
#include "runtime/shader_program.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/gl_suite.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(gfield::build_paths::test_tmp()) / "mesh_intersection";
constexpr int kSize = 128;
constexpr int kDepth = 4;

class MeshIntersection : public test::GlSuite {};

/// The reference tracer's picture of `scene` at kSize^2: `spp` jittered samples per pixel, or
/// (spp = 0) the pixel centres.
Image reference_render(const Scene& scene, int spp) {
  ReferenceTracer tracer;
  std::string error;
  EXPECT_TRUE(tracer.build(scene, error)) << error;
  RenderOptions options;
  options.width = options.height = kSize;
  options.samples_per_pixel = std::max(spp, 1);
  options.max_depth = kDepth;
  options.jitter = spp > 0;
  return clamped_to_display(tracer.render(options));
}

/// The example scene `name` with no assets at all: its meshes can only be traced by their BVHs.
bool load_without_assets(const std::string& name, Scene& scene) {
  std::vector<std::string> warnings;
  std::string error;
  const bool loaded =
      load_scene_file(std::string(gfield::build_paths::data_dir()) + "/scenes/" + name + ".json",
                      scene, warnings, error);
  EXPECT_TRUE(loaded) << error;
  for (MeshAsset& mesh : scene.meshes) {
    mesh.geometry_image.clear();
    mesh.geometry_field.clear();
  }
  return loaded;
}

TEST_F(MeshIntersection, BvhRendersEveryMeshSceneWithinTheReferenceTracersPrecision) {
  for (const char* name : {"mirror-torus-instances", "textured-mirror", "davis-wyman-color-chart",
                           "hurley-water-glass", "mukai-plate-tilt05-w02", "mukai-plate-tilt05-w10",
                           "mukai-plate-tilt30-w02", "mukai-plate-tilt30-w10"}) {
    SCOPED_TRACE(name);
    Scene scene;
    if (!load_without_assets(name, scene))
      continue;
    GpuScene gpu;
    GeometryFieldMethod method;
    std::string error;
    ASSERT_TRUE(gpu.load(scene, error)) << error;
    ASSERT_TRUE(method.load(gpu, default_shader_dir(), error)) << error;
    method.settings().max_depth = kDepth;
    EXPECT_NE(method.status().find("(no field)"), std::string::npos) << method.status();
    const Image view = clamped_to_display(render_image(method, scene.camera, kSize, kSize, 1));
    const Image truth = reference_render(scene, 16);
    const Image centres = reference_render(scene, 0);
    const double bound = compare_images(centres, truth).psnr;
    const double psnr = compare_images(view, truth).psnr;
    std::printf("%-26s BVH %.2f dB, the reference tracer's own %.2f dB (against its 16 spp)\n",
                name, psnr, bound);
    EXPECT_GE(psnr, bound - 0.5);
    if (psnr < bound - 0.5) {  // the pictures, to look at
      fs::create_directories(kDir);
      save_image((kDir / (std::string(name) + "-bvh.png")).string(), view, error);
      save_image((kDir / (std::string(name) + "-reference.png")).string(), centres, error);
    }
  }
}

}  // namespace
}  // namespace gfield
