// The glass method (Mukai et al. 2013) headless against the reference ray tracer (the library
// behind `gfield render`, which treats the plate and the cylinder as real dielectric solids):
// same scene, same sample positions (strata centres), PSNR over the pixels behind the glass.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "geometry/analytic_primitives.hpp"
#include "geometry/scene_file.hpp"
#include "gfield/image_metrics.hpp"
#include "gfield/scene.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/methods/glass.hpp"
#include "runtime/shader_program.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/gl_suite.hpp"

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

/// Straight eye line of pixel (x, y) against a hollow cylinder (object space): the class of its
/// peeled surface codes (runtime/methods/glass.cpp; -1 rims and other patterns) and its distance
/// from the axis in the plane across the axis, relative to the inner radius.
int cylinder_line_class(const Scene& scene, const SceneObject& glass, int width, int height, int x,
                        int y, double& impact) {
  const glm::dmat4 to_object = glm::inverse(object_to_world(glass.transform));
  const CameraRay r = camera_ray(scene.camera, width, height, {x + 0.5, y + 0.5});
  const glm::dvec3 o(to_object * glm::dvec4(r.origin, 1.0));
  const glm::dvec3 d(to_object * glm::dvec4(r.direction, 0.0));
  const double inner = double(glass.shape.radius) - double(glass.shape.thickness);
  impact = std::abs(o.x * d.z - o.z * d.x) / std::sqrt(d.x * d.x + d.z * d.z) / inner;
  std::vector<int> codes;
  double t_min = 0.0;
  PrimitiveHit hit;
  while (codes.size() < 5 && intersect_shape(glass.shape, o, d, t_min, 1e30, hit)) {
    const glm::dvec3 p = o + hit.t * d;
    const double rp = std::sqrt(p.x * p.x + p.z * p.z);
    const int surface = std::abs(hit.normal.y) > 0.5                               ? 2
                        : std::abs(rp - inner) < std::abs(rp - glass.shape.radius) ? 1
                                                                                   : 0;
    codes.push_back(2 * surface + (glm::dot(d, hit.normal) < 0.0 ? 0 : 1));
    t_min = hit.t * (1.0 + 1e-9) + 1e-9;
  }
  if (codes.empty())
    return 0;
  if (codes == std::vector<int>{0, 3, 2, 1})
    return 4;
  if (codes == std::vector<int>{0, 1})
    return 5;
  if (codes == std::vector<int>{0, 3})
    return 6;
  if (codes == std::vector<int>{2, 1})
    return 7;
  return -1;
}

/// Where the error of a hollow-cylinder render lies (printed with GFIELD_GLASS_TEST_DUMP): per
/// straight-line class, and across the both-walls and verge classes by distance from the axis.
void print_cylinder_breakdown(const Scene& scene, const Image& image, const Image& reference,
                              const PixelMask& mask) {
  const SceneObject* glass = nullptr;
  for (const SceneObject& o : scene.objects)
    if (o.material.type == MaterialType::kDielectric)
      glass = &o;
  if (glass == nullptr || glass->shape.type != ShapeType::kHollowCylinder)
    return;
  const int kBins = 12;
  const double outer = glass->shape.radius / (glass->shape.radius - glass->shape.thickness);
  double total = 0.0;
  std::map<std::string, std::array<double, 3>> groups;  // pixels, sum of error, sum of squares
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const size_t i = size_t(y) * size_t(image.width) + size_t(x);
      if (!mask[i])
        continue;
      double impact;
      const int c = cylinder_line_class(scene, *glass, image.width, image.height, x, y, impact);
      const glm::dvec3 e = glm::dvec3(image.pixels[i]) - glm::dvec3(reference.pixels[i]);
      const double signed_error = (e.x + e.y + e.z) / 3.0, squared = glm::dot(e, e) / 3.0;
      total += squared;
      char name[64];
      std::snprintf(name, sizeof(name), "class %d", c);
      for (const std::string& key : {std::string(name), std::string("all")}) {
        std::array<double, 3>& g = groups[key];
        g[0] += 1.0;
        g[1] += signed_error;
        g[2] += squared;
      }
      if (c == 4 || c == 5) {
        const double lo = c == 4 ? 0.0 : 1.0, hi = c == 4 ? 1.0 : outer;
        const int bin = std::clamp(int((impact - lo) / (hi - lo) * kBins), 0, kBins - 1);
        std::snprintf(name, sizeof(name), "class %d, b/r %.3f-%.3f", c,
                      lo + (hi - lo) * bin / kBins, lo + (hi - lo) * (bin + 1) / kBins);
        std::array<double, 3>& g = groups[name];
        g[0] += 1.0;
        g[1] += signed_error;
        g[2] += squared;
      }
    }
  }
  for (const auto& [name, g] : groups)
    std::printf("  %-26s %6.0f px  mean error %+.4f  share of squared error %5.1f%%  PSNR %.2f\n",
                name.c_str(), g[0], g[1] / g[0], 100.0 * g[2] / total, psnr_from_mse(g[2] / g[0]));
}

/// `image` minus `reference` for looking at (GFIELD_GLASS_TEST_DUMP), each pixel 4 x 4: red
/// where `image` is brighter, blue where it is darker (0.25 saturates), grey outside `mask`.
Image signed_difference(const Image& image, const Image& reference, const PixelMask& mask) {
  const int zoom = 4;
  Image out(image.width * zoom, image.height * zoom);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const size_t i = size_t(y / zoom) * size_t(image.width) + size_t(x / zoom);
      const glm::vec3 e = image.pixels[i] - reference.pixels[i];
      const float v = std::clamp(4.0f * (e.x + e.y + e.z) / 3.0f, -1.0f, 1.0f);
      out.pixels[size_t(y) * size_t(out.width) + size_t(x)] = !mask[i] ? glm::vec3(0.05f)
                                                              : v > 0.0f
                                                                  ? glm::vec3(v, 0.0f, 0.0f)
                                                                  : glm::vec3(0.0f, 0.0f, -v);
    }
  }
  return out;
}

/// Class images drawn per sample (FrameStats sums them over the kSamples samples).
int class_images(const FrameStats& stats) {
  return int(stats.count("class images")) / kSamples;
}

/// Both renders of a scene file of data/scenes, compared behind the glass, into `out`; fatal
/// failure when the scene, the tracer or the renderer fails to load (callers wrap it in
/// ASSERT_NO_FATAL_FAILURE).
void compare_scene(const std::string& name, ImageComparison& out, FrameStats* stats = nullptr,
                   ImageComparison* no_fresnel = nullptr, ImageComparison* traced_verge = nullptr) {
  std::string error;
  Scene scene;
  ASSERT_TRUE(
      load_scene(std::string(gfield::build_paths::data_dir()) + "/scenes/" + name, scene, error))
      << error;
  ReferenceTracer tracer;
  ASSERT_TRUE(tracer.build(scene, error)) << error;
  RenderOptions options;
  options.width = options.height = kSize;
  options.samples_per_pixel = kSamples;
  options.jitter = false;
  const Image reference = tracer.render(options);

  GpuScene gpu;
  GlassMethod glass;
  ASSERT_TRUE(gpu.load(scene, error)) << error;
  ASSERT_TRUE(glass.load(gpu, default_shader_dir(), error)) << error;
  const auto render = [&] { return render_image(glass, scene.camera, kSize, kSize, kSamples); };
  const Image image = render_image(glass, scene.camera, kSize, kSize, kSamples, stats);
  const PixelMask mask = glass_mask(scene, kSize, kSize);
  if (no_fresnel != nullptr) {
    glass.settings().fresnel = false;
    *no_fresnel = compare_images(render(), reference, mask);
    glass.settings().fresnel = true;
  }
  if (traced_verge != nullptr) {
    glass.settings().trace_verge = true;
    const Image traced_image = render();
    *traced_verge = compare_images(traced_image, reference, mask);
    if (const char* dump = std::getenv("GFIELD_GLASS_TEST_DUMP")) {
      save_image(std::string(dump) + "/" + name + ".traced-verge.difference.png",
                 signed_difference(traced_image, reference, mask), error);
      std::printf("verge traced per pixel:\n");
      print_cylinder_breakdown(scene, traced_image, reference, mask);
    }
  }
  if (const char* dump = std::getenv("GFIELD_GLASS_TEST_DUMP")) {
    save_image(std::string(dump) + "/" + name + ".glass.exr", image, error);
    save_image(std::string(dump) + "/" + name + ".reference.exr", reference, error);
    save_image(std::string(dump) + "/" + name + ".glass.png", image, error);
    save_image(std::string(dump) + "/" + name + ".reference.png", reference, error);
    save_image(std::string(dump) + "/" + name + ".difference.png",
               signed_difference(image, reference, mask), error);
    print_cylinder_breakdown(scene, image, reference, mask);
  }
  out = compare_images(image, reference, mask);
}

class GlassTest : public test::GlSuite {};

// Thresholds: the target for the plates (30 dB; measured 31.6-36.0 dB at this size).
// The cylinder measures 34.0 dB with its verge displaced (threshold 33.5) and 38.6 dB with the
// verge traced per pixel (GlassSettings::trace_verge; threshold 38.0); the target is
// 25 dB. docs/glass.md has the 512^2 figures.
TEST_F(GlassTest, PlateScenesMatchTheReferenceBehindTheGlass) {
  const struct {
    const char* name;
    double min_psnr;
  } scenes[] = {{"mukai-plate-tilt05-w02.json", 30.0},
                {"mukai-plate-tilt05-w10.json", 30.0},
                {"mukai-plate-tilt30-w02.json", 30.0},
                {"mukai-plate-tilt30-w10.json", 30.0}};
  for (const auto& scene : scenes) {
    FrameStats stats;
    ImageComparison plain;
    ImageComparison c;
    ASSERT_NO_FATAL_FAILURE(compare_scene(scene.name, c, &stats, &plain));
    std::printf(
        "%s: PSNR %.2f dB (without Fresnel %.2f dB), SSIM %.4f over %zu pixels, %d class "
        "images\n",
        scene.name, c.psnr, plain.psnr, c.ssim, c.pixels, class_images(stats));
    EXPECT_GT(c.pixels, size_t(kSize * kSize / 20)) << scene.name;
    EXPECT_GE(c.psnr, scene.min_psnr) << scene.name;
    // The Fresnel terms are not decoration: they bring the picture closer to the reference.
    EXPECT_GT(c.psnr, plain.psnr + 1.0) << scene.name;
  }
}

TEST_F(GlassTest, HollowCylinderMatchesTheReferenceBehindTheGlass) {
  FrameStats stats;
  ImageComparison traced;
  ImageComparison c;
  ASSERT_NO_FATAL_FAILURE(compare_scene("mukai-hollow-cylinder.json", c, &stats, nullptr, &traced));
  std::printf(
      "mukai-hollow-cylinder.json: PSNR %.2f dB (verge traced per pixel %.2f dB), SSIM "
      "%.4f over %zu pixels, %d class images\n",
      c.psnr, traced.psnr, c.ssim, c.pixels, class_images(stats));
  EXPECT_GT(c.pixels, size_t(kSize * kSize / 20));
  EXPECT_GE(c.psnr, 33.5);
  // None, both walls, verge, front wall and back wall (through the open top) all appear.
  EXPECT_EQ(class_images(stats), 5);
  // Tracing the verge per pixel follows its fold exactly.
  EXPECT_GE(traced.psnr, 38.0);
}

/// mukai-plate-tilt05-w02 with the teapot replaced by spot-painted (its own texture, or none),
/// partly behind the plate, read as the tools read it.
Scene textured_plate_scene(const std::string& texture) {
  const std::filesystem::path source =
      std::filesystem::path(gfield::build_paths::data_dir()) / "scenes/mukai-plate-tilt05-w02.json";
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(source));
  nlohmann::json& spot = scene["objects"][0];
  spot["name"] = "spot";
  spot["file"] = std::string(gfield::build_paths::mesh_dir()) + "/spot-painted.obj";
  spot["transform"] = {{"translate", {0.6, 0.75, -0.5}}, {"rotate", {0, -30, 0}}};
  spot["material"] = {{"type", "diffuse"}, {"texture", texture}};
  const std::filesystem::path file = std::filesystem::path(gfield::build_paths::test_tmp()) /
                                     ("glass-textured-" + texture + ".json");
  std::ofstream(file) << scene.dump();
  Scene out;
  std::vector<std::string> warnings;
  std::string error;
  EXPECT_TRUE(load_scene_file(file.string(), out, warnings, error, OutsidePaths::kAllowed))
      << error;
  return out;
}

// The glass method draws a textured mesh with its own uvs and texture, behind the glass
// and beside it. Its picture matches the reference of the textured scene much better than the
// reference of the same scene with the texture ignored: the texture is seen, not a plain colour.
TEST_F(GlassTest, TexturedMeshBehindThePlateMatchesTheReference) {
  const Scene textured = textured_plate_scene("mesh");
  const Scene plain = textured_plate_scene("none");
  ASSERT_EQ(textured.objects[0].material.texture, TextureType::kMesh);
  std::string error;
  RenderOptions options;
  options.width = options.height = kSize;
  options.samples_per_pixel = kSamples;
  options.jitter = false;
  ReferenceTracer tracer;
  ASSERT_TRUE(tracer.build(textured, error)) << error;
  const Image reference = clamped_to_display(tracer.render(options));
  ReferenceTracer plain_tracer;
  ASSERT_TRUE(plain_tracer.build(plain, error)) << error;
  const Image plain_reference = clamped_to_display(plain_tracer.render(options));
  GpuScene gpu;
  GlassMethod glass;
  ASSERT_TRUE(gpu.load(textured, error)) << error;
  ASSERT_TRUE(glass.load(gpu, default_shader_dir(), error)) << error;
  const Image image =
      clamped_to_display(render_image(glass, textured.camera, kSize, kSize, kSamples));
  const PixelMask mask = glass_mask(textured, kSize, kSize);
  const ImageComparison all = compare_images(image, reference);
  const ImageComparison behind = compare_images(image, reference, mask);
  const ImageComparison untextured = compare_images(image, plain_reference);
  std::printf(
      "textured spot and glass plate: PSNR %.2f dB (behind the glass %.2f dB); against "
      "the untextured reference %.2f dB\n",
      all.psnr, behind.psnr, untextured.psnr);
  // Measured on llvmpipe: 40.0 dB, 35.0 dB behind the glass, 25.6 dB against the untextured one.
  EXPECT_GE(all.psnr, 38.0);
  EXPECT_GE(behind.psnr, 33.0);
  EXPECT_GT(all.psnr, untextured.psnr + 10.0);
}

TEST_F(GlassTest, RefusesScenesWithoutOneSlabOrHollowCylinder) {
  std::string error;
  Scene scene;
  ASSERT_TRUE(
      load_scene(std::string(gfield::build_paths::data_dir()) + "/scenes/two-mirror-spheres.json",
                 scene, error))
      << error;
  GpuScene gpu;
  ASSERT_TRUE(gpu.load(scene, error)) << error;
  GlassMethod glass;
  EXPECT_FALSE(glass.load(gpu, default_shader_dir(), error));
  EXPECT_NE(error.find("two-mirror-spheres.json"), std::string::npos) << error;
}

}  // namespace
}  // namespace gfield
