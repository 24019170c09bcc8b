// The GPU geometry-field lookup (shaders/lib/field_lookup.glsl through the runtime's textures)
// against the CPU lookup (core/field_lookup) for the same rays, in every mode, with the field's
// two layers stored as RG8, RG16 and RG32F (the CPU reading the same codes), and both against
// the exact sphere.

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "geometry/mesh_io.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/gpu_storage.hpp"
#include "gfield/scene.hpp"
#include "runtime/field_probe.hpp"
#include "runtime/shader_program.hpp"
#include "synthetic_assets.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/gl_suite.hpp"

namespace gfield {
namespace {
namespace fs = std::filesystem;

/// Camera-like rays from a viewpoint at the sphere plus random rays crossing the box.
std::vector<Ray> test_rays() {
  std::vector<Ray> rays;
  const glm::vec3 eye(2.5f, 1.4f, 3.1f);
  const glm::vec3 forward = glm::normalize(-eye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(right, forward);
  for (int j = 0; j < 96; ++j) {
    for (int i = 0; i < 96; ++i) {
      const glm::vec2 p = (glm::vec2(i, j) + 0.5f) / 96.0f * 2.0f - 1.0f;
      rays.push_back({eye, forward + 0.32f * (p.x * right + p.y * up), 0.0f});
    }
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.2f, 1.2f);
  for (int k = 0; k < 8192; ++k) {
    const glm::vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    rays.push_back({a, b - a, -10.0f, 10.0f});
  }
  // Rays starting inside the box, half of them on the sphere: the first hit beyond the origin
  // often needs the second layer.
  for (int k = 0; k < 4096; ++k) {
    const glm::vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const glm::vec3 origin = k % 2 == 0 ? a : glm::normalize(a);
    rays.push_back({origin, b - a, 1e-3f});
  }
  return rays;
}

/// Every mode, first and last hit: the GPU lookup against the CPU lookup of the same codes;
/// refined first hits of the camera rays against the exact sphere.
void expect_gpu_agrees(const GpuAssets& assets, const FieldLookup& lookup,
                       const std::vector<Ray>& rays, int bits, int asset = 0) {
  std::string error;
  for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
    for (bool last : {false, true}) {
      ProbeQuery query;
      query.mode = mode;
      query.last_hit = last;
      ProbeResult probe;
      ASSERT_TRUE(probe_rays_gpu(assets, asset, rays, query, 0, default_shader_dir().string(),
                                 probe, error))
          << error;
      const std::vector<glm::vec4>& gpu = probe.hits;
      size_t agree = 0, hits = 0, truth = 0, normals = 0;
      for (size_t i = 0; i < rays.size(); ++i) {
        const FieldHit cpu =
            last ? lookup_last_hit(lookup, rays[i], mode) : lookup_first_hit(lookup, rays[i], mode);
        const bool gpu_hit = gpu[i].x > 0.5f;
        hits += cpu.hit ? 1 : 0;
        if (gpu_hit == cpu.hit &&
            (!cpu.hit || glm::distance(glm::vec2(gpu[i].z, gpu[i].w), cpu.uv) < 1e-3f)) {
          ++agree;
          normals += !cpu.hit || glm::dot(probe.normals[i], cpu.normal) > 0.999f ? 1 : 0;
        }
        // Ground truth for the camera rays (first hit, unbounded t).
        if (!last && i < 96 * 96) {
          const bool exact = test::sphere_hit(rays[i].origin, rays[i].direction) >= 0.0f;
          truth += exact == gpu_hit ? 1 : 0;
        }
      }
      const double agreement = double(agree) / double(rays.size());
      SCOPED_TRACE(std::string(lookup_mode_name(mode)) + (last ? " last" : " first") + ", " +
                   std::to_string(bits) + " bits");
      EXPECT_GE(agreement, 0.999) << agree << " of " << rays.size();
      EXPECT_GT(hits, rays.size() / 4);  // the rays do exercise hits
      EXPECT_EQ(normals, agree) << "the normals of hits that agree";
      if (!last && mode == LookupMode::kRefined) {
        EXPECT_GE(double(truth) / (96.0 * 96.0), 0.99);
      }
      std::printf("%d bits, %s %s: %.4f%% agree, %zu CPU hits of %zu rays\n", bits,
                  lookup_mode_name(mode), last ? "last" : "first", 100.0 * agreement, hits,
                  rays.size());
    }
  }
}

class FieldProbe : public test::GlSuite {};

TEST_F(FieldProbe, GpuLookupAgreesWithCpuLookup) {
  std::string error;
  GeometryImage image;
  GeometryField field;
  test::make_sphere_assets(64, 8, image, field);
  const std::vector<Ray> rays = test_rays();
  for (int bits : {8, 16, 32}) {
    const GeometryField stored = quantized_field(field, bits);  // what the GPU reads
    FieldLookup lookup;
    ASSERT_TRUE(make_field_lookup(stored, image, lookup, error)) << error;
    GpuAssets assets;
    ASSERT_TRUE(assets.upload({&image}, {&field}, bits, error)) << error;
    EXPECT_EQ(assets.assets()[0].field_layers, 2);
    EXPECT_EQ(assets.assets()[0].field_bytes, field_gpu_bytes(field, bits));
    expect_gpu_agrees(assets, lookup, rays, bits);
  }
}

// Rays leaving the surface, looked up as the runtime looks up the mesh a ray leaves
// (gf_trace_leaving): the GPU against the CPU (lookup_first_hit_leaving), refined.
TEST_F(FieldProbe, GpuLookupOfRaysLeavingTheSurfaceAgreesWithCpuLookup) {
  std::string error;
  GeometryImage image;
  GeometryField field;
  test::make_sphere_assets(64, 8, image, field);
  const GeometryField stored = quantized_field(field, 8);
  FieldLookup lookup;
  ASSERT_TRUE(make_field_lookup(stored, image, lookup, error)) << error;
  GpuAssets assets;
  ASSERT_TRUE(assets.upload({&image}, {&field}, 8, error)) << error;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<Ray> rays;
  ProbeQuery query;
  query.self_t_min = 4e-3f;
  for (int k = 0; k < 4096; ++k) {
    const glm::vec3 p = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    const glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    const float facing = glm::dot(p, d) >= 0.0f ? 1.0f : -1.0f;  // the sphere's normal is p
    rays.push_back({p + 1e-3f * facing * p, d, 2e-3f});
    query.self.emplace_back(p + 2e-3f * facing * p, facing);
  }
  ProbeResult probe;
  ASSERT_TRUE(
      probe_rays_gpu(assets, 0, rays, query, 0, default_shader_dir().string(), probe, error))
      << error;
  size_t agree = 0, hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const glm::vec4 self = query.self[i];
    const FieldHit cpu = lookup_first_hit_leaving(lookup, rays[i], glm::vec3(self),
                                                  query.self_t_min, self.w, LookupMode::kRefined);
    const bool gpu_hit = probe.hits[i].x > 0.5f;
    hits += cpu.hit ? 1 : 0;
    agree += gpu_hit == cpu.hit &&
                     (!cpu.hit ||
                      glm::distance(glm::vec2(probe.hits[i].z, probe.hits[i].w), cpu.uv) < 1e-3f)
                 ? 1
                 : 0;
  }
  // Rays into the solid hit the far side; rays out of it miss: about half of each.
  EXPECT_GT(hits, rays.size() / 4);
  EXPECT_LT(hits, 3 * rays.size() / 4);
  EXPECT_GE(double(agree) / double(rays.size()), 0.999);
  query.last_hit = true;
  EXPECT_FALSE(
      probe_rays_gpu(assets, 0, rays, query, 0, default_shader_dir().string(), probe, error));
  EXPECT_EQ(error,
            "probe: rays leaving the surface need a self origin each and look up first hits");
}

/// The same sphere with uv mirrored to (1 - u, 1 - v): texels reversed, field uvs mirrored.
void mirror_uv(GeometryImage& image, GeometryField& field) {
  std::reverse(image.position.begin(), image.position.end());
  std::reverse(image.normal.begin(), image.normal.end());
  std::reverse(image.coverage.begin(), image.coverage.end());
  for (glm::vec2& uv : field.nearest)
    if (uv.x >= 0.0f)  // a hit (the miss code is negative)
      uv = glm::vec2(1.0f) - uv;
  for (glm::vec2& uv : field.interior)
    uv = glm::vec2(1.0f) - uv;
}

// Geometry images of different sizes share one texture array sized to the largest (--size auto
// gives 512^2 and 1024^2 images to the meshes of one scene): the smaller ones share a layer, each
// read from its own square (runtime/image_atlas.hpp).
TEST_F(FieldProbe, ImagesOfDifferentSizesShareTheArray) {
  std::string error;
  const int sizes[3] = {48, 96, 48};
  GeometryImage images[3];
  GeometryField fields[3];
  for (int a = 0; a < 3; ++a)
    test::make_sphere_assets(sizes[a], 8, images[a], fields[a]);
  mirror_uv(images[0], fields[0]);  // so that reading one 48^2 image for the other shows
  GpuAssets assets;
  ASSERT_TRUE(assets.upload({&images[0], &images[1], &images[2]},
                            {&fields[0], &fields[1], &fields[2]}, 8, error))
      << error;
  const std::vector<GpuAsset>& gpu = assets.assets();
  EXPECT_EQ(gpu[1].layer, 0);  // the 96^2 image fills layer 0, the 48^2 ones share layer 1
  EXPECT_EQ(gpu[0].layer, 1);
  EXPECT_EQ(gpu[2].layer, 1);
  EXPECT_EQ(gpu[0].image_origin, glm::ivec2(0, 0));
  EXPECT_EQ(gpu[2].image_origin, glm::ivec2(48, 0));
  const std::vector<Ray> rays = test_rays();
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(gpu[size_t(a)].image_size, sizes[a]);
    const GeometryField stored = quantized_field(fields[a], 8);  // the lookup keeps a pointer
    FieldLookup lookup;
    ASSERT_TRUE(make_field_lookup(stored, images[a], lookup, error)) << error;
    SCOPED_TRACE("asset " + std::to_string(a));
    expect_gpu_agrees(assets, lookup, rays, 8, a);
  }
}

/// Every triangle of `mesh` tested (double precision): the nearest t in [t_min, t_max], or -1;
/// `normal`, that triangle's unit normal.
double brute_force_t(const TriangleMesh& mesh, const Ray& ray, glm::dvec3& normal) {
  const glm::dvec3 o(ray.origin), d(ray.direction);
  double best = -1.0;
  for (const glm::ivec3& f : mesh.triangles) {
    const glm::dvec3 p0 = mesh.positions[size_t(f[0])];
    const glm::dvec3 e1 = mesh.positions[size_t(f[1])] - p0;
    const glm::dvec3 e2 = mesh.positions[size_t(f[2])] - p0;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0)
      continue;
    const glm::dvec3 r = o - p0, q = glm::cross(r, e1);
    const double u = glm::dot(r, p) / det, v = glm::dot(d, q) / det, t = glm::dot(e2, q) / det;
    if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t >= ray.t_min && t <= ray.t_max &&
        (best < 0.0 || t < best)) {
      best = t;
      normal = glm::normalize(glm::cross(e1, e2));
    }
  }
  return best;
}

// The probe's BVH route (bench_runtime_complexity times it beside the lookup): spot's BVH as the
// runtime loads it, against every triangle tested, for segments through its box: the same hits
// and misses, the same t, and a shading normal on the hit triangle's side.
TEST_F(FieldProbe, BvhProbeFindsTheNearestTriangle) {
  const fs::path dir =
      fs::path(gfield::build_paths::test_tmp()) / ("field_probe_bvh_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string mesh_file = std::string(gfield::build_paths::mesh_dir()) + "/spot.obj";
  const nlohmann::json scene_json = {
      {"camera", {{"position", {0, 0, 3}}, {"target", {0, 0, 0}}}},
      {"objects", {{{"shape", "mesh"}, {"file", mesh_file}, {"material", {{"type", "mirror"}}}}}}};
  std::ofstream(dir / "scene.json") << scene_json.dump();
  Scene scene;
  TriangleMesh mesh;
  std::string error;
  ASSERT_TRUE(load_scene((dir / "scene.json").string(), scene, error, OutsidePaths::kAllowed))
      << error;
  ASSERT_TRUE(load_mesh(mesh_file, mesh, error)) << error;
  AssetNeeds needs;
  needs.bvhs = true;
  GpuAssets assets;
  ASSERT_TRUE(assets.require(scene, needs, error)) << error;
  const Box box = assets.asset(0).mesh_bounds;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Ray> rays;
  for (int k = 0; k < 2048; ++k) {
    const glm::vec3 a = box.min + (box.max - box.min) * glm::vec3(u(rng), u(rng), u(rng));
    const glm::vec3 b = box.min + (box.max - box.min) * glm::vec3(u(rng), u(rng), u(rng));
    rays.push_back({2.0f * a - b, b - a, 0.0f, 3.0f});
  }
  ProbeQuery query;
  query.bvh = true;
  ProbeResult probe;
  ASSERT_TRUE(
      probe_rays_gpu(assets, 0, rays, query, 1, default_shader_dir().string(), probe, error))
      << error;
  size_t agree = 0, hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    glm::dvec3 face(0.0);
    const double t = brute_force_t(mesh, rays[i], face);
    const bool hit = probe.hits[i].x > 0.5f;
    const glm::dvec3 normal(probe.normals[i]);
    hits += t >= 0.0 ? 1 : 0;
    agree += hit == (t >= 0.0) && (!hit || std::abs(probe.hits[i].y - t) < 1e-4 * (1.0 + t)) &&
                     (!hit ||
                      (std::abs(glm::length(normal) - 1.0) < 1e-4 && glm::dot(normal, face) > 0.3))
                 ? 1
                 : 0;
  }
  EXPECT_GT(hits, rays.size() / 4);  // the rays do exercise hits
  EXPECT_GE(agree, rays.size() - 2) << "of " << rays.size() << " rays";
  EXPECT_GT(probe.ms, 0.0);
  EXPECT_FALSE(
      probe_rays_gpu(assets, 1, rays, query, 0, default_shader_dir().string(), probe, error));
  EXPECT_EQ(error, "probe: no asset 1");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gfield
