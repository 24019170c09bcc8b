// The glass method (Mukai et al. 2013) headless against the reference ray tracer (the library
// behind `gfield render`, which treats the plate and the cylinder as real dielectric solids):
// same scene, same sample positions (strata centres), PSNR over the pixels behind the glass.

#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "gfield/image_metrics.hpp"
#include "gfield/scene.hpp"
#include "preprocess/analytic_primitives.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/methods/glass.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {
namespace {

constexpr int kSize = 160;
constexpr int kSamples = 4;  // per pixel, both renderers, at the same positions

/// Pixels whose centre's eye ray meets the scene's dielectric object ("behind the glass").
PixelMask glass_mask(const Scene& scene, int width, int height) {
  PixelMask mask(size_t(width) * size_t(height), false);
  for (const SceneObject& o : scene.objects) {
    if (o.material.type != MaterialType::kDielectric)
      continue;
    const glm::dmat4 to_object = glm::inverse(object_to_world(o.transform));
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const CameraRay r = camera_ray(scene.camera, width, height, {x + 0.5, y + 0.5});
        PrimitiveHit hit;
        if (intersect_shape(o.shape, glm::dvec3(to_object * glm::dvec4(r.origin, 1.0)),
                            glm::dvec3(to_object * glm::dvec4(r.direction, 0.0)), 0.0, 1e30, hit))
          mask[size_t(y) * size_t(width) + size_t(x)] = true;
      }
    }
  }
  return mask;
}

/// Both renders of a scene file of data/scenes, compared behind the glass.
ImageComparison compare_scene(const std::string& name, GlassStats* stats = nullptr,
                              ImageComparison* no_fresnel = nullptr,
                              ImageComparison* traced_verge = nullptr) {
  std::string error;
  Scene scene;
  EXPECT_TRUE(load_scene(std::string(GFIELD_DATA_DIR) + "/scenes/" + name, scene, error)) << error;
  ReferenceTracer tracer;
  EXPECT_TRUE(tracer.build(scene, error)) << error;
  RenderOptions options;
  options.width = options.height = kSize;
  options.samples_per_pixel = kSamples;
  options.jitter = false;
  const Image reference = tracer.render(options);

  GlassRenderer renderer;
  GlassSettings settings;
  settings.samples_per_pixel = kSamples;
  EXPECT_TRUE(renderer.load(scene, default_shader_dir(), settings, error)) << error;
  const Image image = renderer.render_image(kSize, kSize, settings, stats);
  const PixelMask mask = glass_mask(scene, kSize, kSize);
  if (no_fresnel != nullptr) {
    GlassSettings plain = settings;
    plain.fresnel = false;
    *no_fresnel = compare_images(renderer.render_image(kSize, kSize, plain), reference, mask);
  }
  if (traced_verge != nullptr) {
    GlassSettings traced = settings;
    traced.trace_verge = true;
    *traced_verge = compare_images(renderer.render_image(kSize, kSize, traced), reference, mask);
  }
  if (const char* dump = std::getenv("GFIELD_GLASS_TEST_DUMP")) {
    save_image(std::string(dump) + "/" + name + ".glass.exr", image, error);
    save_image(std::string(dump) + "/" + name + ".reference.exr", reference, error);
  }
  return compare_images(image, reference, mask);
}

class GlassTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    context_ = GlContext::create_headless(error).release();
    ASSERT_NE(context_, nullptr) << error;
  }
  static void TearDownTestSuite() {
    delete context_;
    context_ = nullptr;
  }
  static GlContext* context_;
};
GlContext* GlassTest::context_ = nullptr;

// Thresholds: the target for the plates (30 dB; measured 30.8-32.5 dB at this size).
// The cylinder reaches 24.6 dB with its verge displaced (threshold 24.1) and 26.5 dB with the
// verge traced per pixel (GlassSettings::trace_verge; the target is 25 dB);
// docs/glass.md has the 512^2 figures.
TEST_F(GlassTest, PlateScenesMatchTheReferenceBehindTheGlass) {
  const struct {
    const char* name;
    double min_psnr;
  } scenes[] = {{"mukai-plate-tilt05-w02.json", 30.0},
                {"mukai-plate-tilt05-w10.json", 30.0},
                {"mukai-plate-tilt30-w02.json", 30.0},
                {"mukai-plate-tilt30-w10.json", 30.0}};
  for (const auto& scene : scenes) {
    GlassStats stats;
    ImageComparison plain;
    const ImageComparison c = compare_scene(scene.name, &stats, &plain);
    std::printf(
        "%s: PSNR %.2f dB (without Fresnel %.2f dB), SSIM %.4f over %zu pixels, %d class "
        "images\n",
        scene.name, c.psnr, plain.psnr, c.ssim, c.pixels, stats.class_images);
    EXPECT_GT(c.pixels, size_t(kSize * kSize / 20)) << scene.name;
    EXPECT_GE(c.psnr, scene.min_psnr) << scene.name;
    // The Fresnel terms are not decoration: they bring the picture closer to the reference.
    EXPECT_GT(c.psnr, plain.psnr + 1.0) << scene.name;
  }
}

TEST_F(GlassTest, HollowCylinderMatchesTheReferenceBehindTheGlass) {
  GlassStats stats;
  ImageComparison traced;
  const ImageComparison c = compare_scene("mukai-hollow-cylinder.json", &stats, nullptr, &traced);
  std::printf(
      "mukai-hollow-cylinder.json: PSNR %.2f dB (verge traced per pixel %.2f dB), SSIM "
      "%.4f over %zu pixels, %d class images\n",
      c.psnr, traced.psnr, c.ssim, c.pixels, stats.class_images);
  EXPECT_GT(c.pixels, size_t(kSize * kSize / 20));
  EXPECT_GE(c.psnr, 24.1);
  // None, both walls, verge, front wall and back wall (through the open top) all appear.
  EXPECT_EQ(stats.class_images, 5);
  // With the verge traced per pixel the 25 dB holds.
  EXPECT_GE(traced.psnr, 26.0);
}

TEST_F(GlassTest, RefusesScenesWithoutOneSlabOrHollowCylinder) {
  std::string error;
  Scene scene;
  ASSERT_TRUE(
      load_scene(std::string(GFIELD_DATA_DIR) + "/scenes/two-mirror-spheres.json", scene, error))
      << error;
  GlassRenderer renderer;
  EXPECT_FALSE(renderer.load(scene, default_shader_dir(), GlassSettings{}, error));
  EXPECT_NE(error.find("two-mirror-spheres.json"), std::string::npos) << error;
}

}  // namespace
}  // namespace gfield
