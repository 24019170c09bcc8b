// The reference tracer against analytic answers: an index-1 sphere is invisible, a mirror quad
// shows the exact mirror image of a pattern, a glass slab shifts rays by Mukai et al.'s
// equation 2, total internal reflection happens exactly beyond the critical angle, Fresnel
// R + T = 1, Beer–Lambert absorption; plus determinism, instancing and the CLI.

#include <gtest/gtest.h>

#include <tbb/global_control.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "gfield/image_metrics.hpp"
#include "gfield/optics.hpp"
#include "preprocess/reference_tracer.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

Scene base_scene(int size) {
  Scene scene;
  scene.filename = "test";
  scene.camera.position = {0.0f, 0.0f, 4.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.fov_degrees = 40.0f;
  scene.width = scene.height = size;
  scene.environment.type = EnvironmentType::kStudio;
  return scene;
}

SceneObject dielectric(ShapeType type, float ior) {
  SceneObject o;
  o.shape.type = type;
  o.material.type = MaterialType::kDielectric;
  o.material.ior = ior;
  return o;
}

Image render(const Scene& scene, const RenderOptions& options) {
  ReferenceTracer tracer;
  std::string error;
  if (!tracer.build(scene, error)) {
    ADD_FAILURE() << error;  // the empty picture compares as no match
    return Image{};
  }
  return tracer.render(options);
}

TEST(ReferenceTracer, IndexOneSphereLeavesTheEnvironmentUnchanged) {
  const Scene empty = base_scene(48);
  Scene scene = empty;
  scene.objects.push_back(dielectric(ShapeType::kSphere, 1.0f));
  RenderOptions options;
  options.samples_per_pixel = 2;
  const Image reference = render(empty, options);
  const ImageComparison c = compare_images(render(scene, options), reference);
  EXPECT_GE(c.psnr, 50.0);
  // The same sphere in glass is far from invisible: the test can fail.
  scene.objects[0].material.ior = 1.5f;
  EXPECT_LT(compare_images(render(scene, options), reference).psnr, 30.0);
}

/// The checker colour of the pattern quad at world point q (quad at z = 3 turned to face -Z:
/// object x = -world x).
glm::vec3 pattern_color(glm::dvec3 q, const Material& m) {
  const double u = -q.x / 20.0 + 0.5, v = q.y / 20.0 + 0.5;
  const int k = int(std::floor(u * 40.0)) + int(std::floor(v * 40.0));
  return m.checker_colors[size_t(k & 1)];
}

TEST(ReferenceTracer, MirrorQuadShowsTheExactMirrorImage) {
  Scene scene = base_scene(64);
  scene.camera.position = {0.3f, 0.2f, 2.0f};
  scene.environment.type = EnvironmentType::kConstant;
  scene.environment.color = glm::vec3(0.0f);
  scene.ambient = glm::vec3(1.0f);
  SceneObject mirror;
  mirror.shape.type = ShapeType::kQuad;
  mirror.shape.size = {4.0f, 4.0f, 0.0f};
  mirror.material.type = MaterialType::kMirror;
  mirror.material.color = glm::vec3(1.0f);
  SceneObject pattern;
  pattern.shape.type = ShapeType::kQuad;
  pattern.shape.size = {20.0f, 20.0f, 0.0f};
  pattern.transform.translate = {0.0f, 0.0f, 3.0f};
  pattern.transform.rotate_degrees = {0.0f, 180.0f, 0.0f};
  pattern.material.texture = TextureType::kChecker;
  pattern.material.checker_colors = {glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)};
  pattern.material.checker_scale = glm::vec2(40.0f);
  scene.objects = {mirror, pattern};
  RenderOptions options;
  options.samples_per_pixel = 1;
  options.jitter = false;  // pixel centres
  const Image image = render(scene, options);
  ASSERT_EQ(image.pixels.size(), size_t(64 * 64));
  int exact = 0, red = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const CameraRay ray = camera_ray(scene.camera, 64, 64, {x + 0.5, y + 0.5});
      // Analytic: hit the mirror plane z = 0, reflect (negate z), hit the plane z = 3.
      const glm::dvec3 p = ray.origin - ray.origin.z / ray.direction.z * ray.direction;
      ASSERT_LT(std::abs(p.x), 2.0);
      ASSERT_LT(std::abs(p.y), 2.0);
      const glm::dvec3 r(ray.direction.x, ray.direction.y, -ray.direction.z);
      const glm::dvec3 q = p + (3.0 - p.z) / r.z * r;
      const glm::vec3 expected = pattern_color(q, pattern.material);
      exact += glm::length(image.at(x, y) - expected) < 1e-6f;
      red += expected.r > 0.5f;
    }
  }
  EXPECT_GT(red, 64 * 64 / 4);  // both colours are seen
  EXPECT_LT(red, 64 * 64 * 3 / 4);
  EXPECT_GE(exact, 64 * 64 - 4) << "pixels off the analytic mirror image: " << 64 * 64 - exact;
}

/// Mukai et al. 2013, eq. 2: the shift along the plate normal L = W (1 - tan(phi) tan(pi/2 -
/// theta)).
double mukai_shift(double w, double theta, double n) {
  const double phi = std::asin(std::sin(theta) / n);
  return w * (1.0 - std::tan(phi) * std::tan(kPi / 2.0 - theta));
}

TEST(ReferenceTracer, GlassSlabShiftsRaysByMukaiEquation2) {
  for (const float tilt : {5.0f, 30.0f}) {
    for (const float w : {0.2f, 1.0f}) {
      Scene scene = base_scene(8);
      SceneObject slab = dielectric(ShapeType::kSlab, 1.5f);
      slab.shape.size = {50.0f, 50.0f, 0.0f};
      slab.shape.thickness = w;
      slab.transform.rotate_degrees = {0.0f, tilt, 0.0f};
      slab.transform.translate = {0.3f, -0.2f, 0.1f};
      scene.objects = {slab};
      ReferenceTracer tracer;
      std::string error;
      ASSERT_TRUE(tracer.build(scene, error)) << error;
      const double a = glm::radians(double(tilt));
      const glm::dvec3 normal(std::sin(a), 0.0, std::cos(a));    // plate normal (+Z turned)
      const glm::dvec3 tangent(std::cos(a), 0.0, -std::sin(a));  // in the plate, in xz
      for (const double degrees : {0.0, 10.0, 30.0, 45.0, 60.0, 75.0}) {
        const double theta = glm::radians(degrees);
        const glm::dvec3 d = -(std::cos(theta) * normal) + std::sin(theta) * tangent;
        const glm::dvec3 origin = glm::dvec3(0.3, -0.2, 0.1) + 5.0 * normal - 2.0 * tangent;
        const std::vector<PathEvent> path = tracer.follow_path({origin, d}, 8);
        ASSERT_EQ(path.size(), 3u);
        ASSERT_EQ(path[0].kind, PathEvent::kEnter);
        ASSERT_EQ(path[1].kind, PathEvent::kExit);
        ASSERT_EQ(path[2].kind, PathEvent::kEscape);
        // Leaves parallel to the incoming direction.
        EXPECT_NEAR(glm::length(glm::cross(path[1].direction, d)), 0.0, 2e-6) << degrees;
        EXPECT_GT(glm::dot(path[1].direction, d), 0.0);
        // Entry-to-exit offset = s d + L n_in (coplanar): solve for L.
        const glm::dvec3 offset = path[1].position - path[0].position;
        const glm::dvec3 n_in = -normal;
        const double c = glm::dot(d, n_in);
        if (degrees == 0.0) {
          EXPECT_NEAR(glm::length(glm::cross(offset, d)), 0.0, 1e-6);  // no shift
          EXPECT_NEAR(glm::length(offset), w, 1e-6);
          continue;
        }
        const double od = glm::dot(offset, d), on = glm::dot(offset, n_in);
        const double s = (od - c * on) / (1.0 - c * c);
        const double shift = (on - c * od) / (1.0 - c * c);
        EXPECT_NEAR(glm::length(offset - s * d - shift * n_in), 0.0, 1e-6);
        EXPECT_NEAR(shift, mukai_shift(w, theta, 1.5), 2e-6 * w)
            << "tilt " << tilt << " w " << w << " theta " << degrees;
        // The same shift as the textbook lateral displacement W sin(theta - phi) / cos(phi).
        const double phi = std::asin(std::sin(theta) / 1.5);
        EXPECT_NEAR(shift * std::sin(theta), w * std::sin(theta - phi) / std::cos(phi), 1e-5);
      }
    }
  }
}

TEST(ReferenceTracer, TotalInternalReflectionExactlyBeyondTheCriticalAngle) {
  for (const float ior : {1.5f, 1.33333f, 2.417f}) {
    Scene scene = base_scene(8);
    SceneObject box = dielectric(ShapeType::kBox, ior);
    box.shape.size = {200.0f, 4.0f, 200.0f};  // the +Y face is hit first up to 88.8 degrees
    scene.objects = {box};
    ReferenceTracer tracer;
    std::string error;
    ASSERT_TRUE(tracer.build(scene, error)) << error;
    const double critical = std::asin(1.0 / double(ior));
    int tir = 0, refracted = 0;
    for (double degrees = 0.25; degrees < 88.5; degrees += 0.25) {
      const double alpha = glm::radians(degrees);
      if (std::abs(alpha - critical) < 1e-4)
        continue;
      const glm::dvec3 d(std::sin(alpha), std::cos(alpha), 0.0);  // towards the +Y face
      const std::vector<PathEvent> path = tracer.follow_path({glm::dvec3(0.0), d}, 1);
      ASSERT_EQ(path.size(), 1u);
      EXPECT_NEAR(path[0].position.y, 2.0, 1e-9);
      if (alpha > critical) {
        ++tir;
        EXPECT_EQ(path[0].kind, PathEvent::kTotalInternalReflection) << degrees;
        EXPECT_NEAR(glm::length(path[0].direction - glm::dvec3(d.x, -d.y, 0.0)), 0.0, 1e-6);
      } else {
        ++refracted;
        EXPECT_EQ(path[0].kind, PathEvent::kExit) << degrees;
        // Snell: sin(out) = n sin(in).
        EXPECT_NEAR(path[0].direction.x, double(ior) * std::sin(alpha), 1e-5);
      }
    }
    EXPECT_GT(tir, 10);
    EXPECT_GT(refracted, 10);
  }
}

TEST(ReferenceTracer, FresnelReflectancePlusTransmittanceIsOne) {
  for (const auto& [n1, n2] : {std::pair{1.0, 1.5}, std::pair{1.5, 1.0}, std::pair{1.0, 2.417}}) {
    for (double degrees = 0.0; degrees < 90.0; degrees += 1.0) {
      const double ci = std::cos(glm::radians(degrees));
      const glm::dvec3 incident(std::sqrt(1.0 - ci * ci), -ci, 0.0);
      const InterfaceSplit s =
          split_at_interface(incident, {0.0, 1.0, 0.0}, n1, n2, DielectricMode::kFull);
      EXPECT_NEAR(s.reflected_weight + s.transmitted_weight, 1.0, 1e-12);
      const double sin_t = n1 / n2 * std::sqrt(1.0 - ci * ci);
      if (sin_t >= 1.0) {
        EXPECT_TRUE(s.total_internal_reflection);
        EXPECT_EQ(s.reflected_weight, 1.0);
        continue;
      }
      // Transmittance from the amplitude coefficients (Born & Wolf), independent of R:
      // T = (n2 cos t / n1 cos i) (ts^2 + tp^2) / 2.
      const double ct = std::sqrt(1.0 - sin_t * sin_t);
      const double ts = 2.0 * n1 * ci / (n1 * ci + n2 * ct);
      const double tp = 2.0 * n1 * ci / (n2 * ci + n1 * ct);
      const double t = (n2 * ct) / (n1 * ci) * 0.5 * (ts * ts + tp * tp);
      EXPECT_NEAR(s.transmitted_weight, t, 2e-6) << n1 << " " << n2 << " " << degrees;
    }
  }
}

TEST(ReferenceTracer, ClearGlassConservesEnergyAndAbsorptionFollowsBeerLambert) {
  Scene scene = base_scene(24);
  scene.camera.position = {0.0f, 0.0f, 3.0f};
  scene.camera.fov_degrees = 30.0f;
  scene.environment.type = EnvironmentType::kConstant;
  const glm::vec3 sky(0.5f, 0.25f, 1.0f);
  scene.environment.color = sky;
  SceneObject slab = dielectric(ShapeType::kSlab, 1.5f);
  slab.shape.size = {40.0f, 40.0f, 0.0f};
  slab.shape.thickness = 0.5f;
  slab.transform.rotate_degrees = {10.0f, 20.0f, 0.0f};
  scene.objects = {slab};
  RenderOptions options;
  options.samples_per_pixel = 1;
  // Every path ends in the sky: with R + T = 1 at each interface the image is the sky colour.
  for (const Image& image : {render(scene, options)}) {
    for (const glm::vec3& p : image.pixels) {
      EXPECT_NEAR(p.x, sky.x, 2e-4f);
      EXPECT_NEAR(p.z, sky.z, 4e-4f);
    }
  }
  // Absorption: refract-only at normal incidence through thickness 0.5: exp(-sigma W).
  scene.objects[0].transform.rotate_degrees = glm::vec3(0.0f);
  scene.objects[0].material.absorption = {0.2f, 1.0f, 3.0f};
  ReferenceTracer tracer;
  std::string error;
  ASSERT_TRUE(tracer.build(scene, error)) << error;
  options.dielectric = DielectricMode::kRefractOnly;
  const glm::dvec3 straight = tracer.trace({{0.0, 0.0, 3.0}, {0.0, 0.0, -1.0}}, options);
  EXPECT_NEAR(straight.x, 0.5 * std::exp(-0.2 * 0.5), 1e-6);
  EXPECT_NEAR(straight.y, 0.25 * std::exp(-1.0 * 0.5), 1e-6);
  EXPECT_NEAR(straight.z, 1.0 * std::exp(-3.0 * 0.5), 1e-6);
  // Oblique: the path inside is W / cos(phi).
  const double theta = glm::radians(40.0), phi = std::asin(std::sin(theta) / 1.5);
  const glm::dvec3 d(std::sin(theta), 0.0, -std::cos(theta));
  const glm::dvec3 oblique = tracer.trace({{-2.0 * d.x, 0.0, 2.0 * std::cos(theta)}, d}, options);
  EXPECT_NEAR(oblique.z, std::exp(-3.0 * 0.5 / std::cos(phi)), 1e-6);
}

TEST(ReferenceTracer, HollowCylinderRefractsFourTimes) {
  Scene scene = base_scene(8);
  SceneObject glass = dielectric(ShapeType::kHollowCylinder, 1.5f);
  glass.shape.radius = 1.0f;
  glass.shape.thickness = 0.1f;
  glass.shape.height = 3.0f;
  scene.objects = {glass};
  ReferenceTracer tracer;
  std::string error;
  ASSERT_TRUE(tracer.build(scene, error)) << error;
  const auto path = tracer.follow_path({{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}}, 8);
  ASSERT_EQ(path.size(), 5u);
  const double z[4] = {1.0, 0.9, -0.9, -1.0};
  const PathEvent::Kind kinds[4] = {PathEvent::kEnter, PathEvent::kExit, PathEvent::kEnter,
                                    PathEvent::kExit};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(path[size_t(k)].kind, kinds[k]);
    EXPECT_NEAR(path[size_t(k)].position.z, z[k], 1e-7f);
  }
  EXPECT_EQ(path[4].kind, PathEvent::kEscape);
  // Off axis: four refractions and a deviated ray.
  const auto off = tracer.follow_path({{0.3, 0.0, 5.0}, {0.0, 0.0, -1.0}}, 8);
  ASSERT_EQ(off.size(), 5u);
  EXPECT_GT(std::abs(off[3].direction.x), 1e-3);
}

TEST(ReferenceTracer, MeshInstancesSitWhereTheirTransformsPutThem) {
  Scene scene = base_scene(8);
  MeshAsset torus_mesh;
  torus_mesh.file = std::string(gfield::build_paths::data_dir()) + "/meshes/torus.obj";
  scene.meshes.push_back(torus_mesh);
  for (const float x : {-3.0f, 3.0f}) {
    SceneObject torus;
    torus.shape.type = ShapeType::kMesh;
    torus.shape.mesh = 0;
    torus.transform.translate = {x, 0.0f, 0.0f};
    torus.material.type = MaterialType::kMirror;
    scene.objects.push_back(torus);
  }
  ReferenceTracer tracer;
  std::string error;
  ASSERT_TRUE(tracer.build(scene, error)) << error;
  // Straight down onto the top of each tube (major radius 1, minor 0.4): y = 0.4.
  for (const double x : {-4.0, -2.0, 2.0, 4.0}) {
    const auto path = tracer.follow_path({{x, 5.0, 0.0}, {0.0, -1.0, 0.0}}, 1);
    ASSERT_EQ(path[0].kind, PathEvent::kMirror) << x;
    EXPECT_NEAR(path[0].position.y, 0.4, 1e-5) << x;
    EXPECT_NEAR(path[0].direction.y, 1.0, 1e-4) << x;
    EXPECT_EQ(path[0].object, x < 0.0 ? 0 : 1);
  }
  // Through the holes: nothing.
  for (const double x : {-3.0, 3.0}) {
    EXPECT_EQ(tracer.follow_path({{x, 5.0, 0.0}, {0.0, -1.0, 0.0}}, 1)[0].kind, PathEvent::kEscape);
  }
}

TEST(ReferenceTracer, DeterministicAcrossRunsAndThreadCounts) {
  Scene scene;
  std::string error;
  ASSERT_TRUE(load_scene(
      std::string(gfield::build_paths::data_dir()) + "/scenes/davis-wyman-color-chart.json", scene,
      error))
      << error;
  RenderOptions options;
  options.width = options.height = 32;
  options.samples_per_pixel = 2;
  const Image a = render(scene, options);
  const Image b = render(scene, options);
  EXPECT_EQ(a.pixels, b.pixels);
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(render(scene, options).pixels, a.pixels);
  }
  options.seed = 2;
  EXPECT_NE(render(scene, options).pixels, a.pixels);
  // The restricted modes differ from the full one where reflection matters.
  options.seed = 1;
  options.dielectric = DielectricMode::kTirOnly;
  EXPECT_NE(render(scene, options).pixels, a.pixels);
}

TEST(ReferenceTracer, EveryExampleSceneRenders) {
  int count = 0;
  for (const auto& entry :
       fs::directory_iterator(fs::path(gfield::build_paths::data_dir()) / "scenes")) {
    if (entry.path().extension() != ".json")
      continue;
    Scene scene;
    std::string error;
    ASSERT_TRUE(load_scene(entry.path().string(), scene, error)) << error;
    RenderOptions options;
    options.width = options.height = 24;
    options.samples_per_pixel = 1;
    options.max_depth = 4;
    const Image image = render(scene, options);
    float lo = 1e30f, hi = -1e30f;
    for (const glm::vec3& p : image.pixels) {
      ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
      lo = std::min(lo, p.y);
      hi = std::max(hi, p.y);
    }
    EXPECT_GT(hi - lo, 0.05f) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 6);
}

TEST(RenderCli, RendersComparesAndRefusesBadInput) {
  const std::string dir = gfield::build_paths::test_tmp();
  const std::string scene_file = dir + "/tracer_cli_scene.json";
  std::ofstream(scene_file) << R"({"purpose": "cli test",
  "camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
  "image": {"width": 16, "height": 12},
  "objects": [{"shape": "sphere", "material": {"type": "dielectric", "ior": "glass"}}]}
)";
  const std::string out = dir + "/tracer_cli_render.exr";
  fs::remove(out);
  auto run = test::run_cli("render " + scene_file + " -o " + out + " --spp 2 --depth 4");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  Image image;
  std::string error;
  ASSERT_TRUE(load_image(out, image, error)) << error;
  EXPECT_EQ(image.width, 16);
  EXPECT_EQ(image.height, 12);
  run = test::run_cli("render " + scene_file + " -o " + dir +
                      "/tracer_cli_render.png --size 20x10 -q");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  run = test::run_cli("compare " + out + " " + out + " --json");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("\"psnr_db\": \"inf\""), std::string::npos) << run.out;
  // Bad scene: one line with file:line:column, exit 2, no output file.
  const std::string bad = dir + "/tracer_cli_bad.json";
  std::ofstream(bad)
      << "{\"camera\": {\"position\": [0, 0, 4], \"target\": [0, 0, 0]},\n"
         "\"objects\": [{\"shape\": \"sphere\", \"material\": {\"type\": \"glas\"}}]}\n";
  fs::remove(dir + "/tracer_cli_bad.exr");
  run = test::run_cli("render " + bad + " -o " + dir + "/tracer_cli_bad.exr");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(bad + ":2:54:"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir + "/tracer_cli_bad.exr"));
  // Huge requests are refused with an estimate.
  run = test::run_cli("render " + scene_file + " -o " + out + " --spp 100000 --size 8192x8192");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("refusing"), std::string::npos) << run.err;
  run = test::run_cli("render " + scene_file + " -o " + out + " --dielectric sometimes");
  EXPECT_EQ(run.exit_code, 2);
  run = test::run_cli("compare " + out + " " + dir + "/tracer_cli_render.png");
  EXPECT_EQ(run.exit_code, 2);  // sizes differ
}

TEST(RenderCli, ComparesARadiancePictureWithADisplayPictureAsDisplayed) {
  // The studio environment's softboxes reach 6: against its clamped PNG, the EXR of the same
  // render differed by them alone (17.5 dB where the pictures agree to 8 bits).
  const std::string dir = gfield::build_paths::test_tmp();
  const std::string scene =
      std::string(gfield::build_paths::data_dir()) + "/scenes/two-mirror-spheres.json";
  const std::string exr = dir + "/display_transform.exr", png = dir + "/display_transform.png";
  for (const std::string& out : {exr, png}) {
    const test::CliRun r =
        test::run_cli("render " + scene + " --size 48x48 --spp 1 --strata-centres -q -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  Image radiance;
  std::string error;
  ASSERT_TRUE(load_image(exr, radiance, error)) << error;
  float brightest = 0.0f;
  for (const glm::vec3& p : radiance.pixels)
    brightest = std::max({brightest, p.x, p.y, p.z});
  ASSERT_GT(brightest, 1.5f) << "the test needs highlights above 1";
  for (const std::string& args : {exr + " " + png, png + " " + exr}) {
    const test::CliRun r = test::run_cli("compare " + args + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["scale"], "display (sRGB 8-bit)");
    // The EXR as its PNG stores it is the PNG: the same values.
    EXPECT_EQ(j["psnr_db"], "inf") << args;
    const test::CliRun lin = test::run_cli("compare " + args + " --json --linear");
    const nlohmann::json k = nlohmann::json::parse(lin.out);
    EXPECT_EQ(k["scale"], "linear light");
    EXPECT_GT(k["psnr_db"].get<double>(), 45.0) << args;  // 8-bit rounding alone
  }
  const test::CliRun same = test::run_cli("compare " + exr + " " + exr + " --json");
  EXPECT_EQ(nlohmann::json::parse(same.out)["scale"], "linear light");
}

}  // namespace
}  // namespace gfield
