// The proxy of a large mesh (mesh_proxy.hpp) and the geometry image built through it: its size,
// that it is made of the mesh's own vertices, that the image's texels lie on the full surface
// (exact distances, closest_point.hpp), its accuracy against the full mesh's own image, and the
// fall back to the full mesh where the proxy's image misses the bound.

#include "preprocess/mesh_proxy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include <fstream>

#include <nlohmann/json.hpp>

#include "preprocess/closest_point.hpp"
#include "preprocess/geometry_image_build.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/midpoint_subdivision.hpp"

namespace gfield {
namespace {

TriangleMesh bundled(const std::string& name) {
  TriangleMesh mesh;
  std::string error;
  EXPECT_TRUE(load_mesh(std::string(gfield::build_paths::mesh_dir()) + "/" + name, mesh, error))
      << error;
  return mesh;
}

TEST(MeshProxy, IsMadeOfTheMeshsOwnVerticesWithoutFoldedPairs) {
  const TriangleMesh bunny = bundled("stanford-bunny.obj");
  MeshProxy proxy;
  std::string error;
  ASSERT_TRUE(make_mesh_proxy(bunny, 10000, proxy, error)) << error;
  EXPECT_EQ(proxy.welded.triangles.size(), bunny.triangles.size());
  EXPECT_LE(proxy.proxy.triangles.size(), 10000u);
  EXPECT_GE(proxy.proxy.triangles.size(), 9000u);
  EXPECT_GT(proxy.error, 0.0);
  const std::set<std::array<double, 3>> input([&] {
    std::set<std::array<double, 3>> s;
    for (const glm::dvec3& p : bunny.positions)
      s.insert({p.x, p.y, p.z});
    return s;
  }());
  for (const glm::dvec3& p : proxy.proxy.positions)
    ASSERT_TRUE(input.count({p.x, p.y, p.z}));
  std::set<std::array<int, 3>> faces;
  for (const glm::ivec3& t : proxy.proxy.triangles) {
    std::array<int, 3> key{t[0], t[1], t[2]};
    std::sort(key.begin(), key.end());
    ASSERT_TRUE(faces.insert(key).second) << "two faces over one vertex triple";
  }
}

TEST(MeshProxy, GenusOfBundledMeshesAndOfANonManifoldOne) {
  EXPECT_EQ(surface_genus(weld_positions(bundled("torus.obj"))), 1);
  EXPECT_EQ(surface_genus(weld_positions(bundled("spot.obj"))), 0);
  EXPECT_EQ(surface_genus(weld_positions(bundled("stanford-bunny.obj"))), 0);  // 5 holes
  EXPECT_EQ(surface_genus(weld_positions(bundled("rocker-arm.obj"))), 1);
  TriangleMesh fin;  // three faces on one edge
  fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  EXPECT_EQ(surface_genus(fin), -1);
}

TEST(MeshProxy, WeldingMergesExactlyCoincidentPositions) {
  TriangleMesh soup;  // two triangles of a square, each with its own corners
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {-0.0, 1, 0}};
  soup.triangles = {{0, 1, 2}, {3, 4, 5}};
  const TriangleMesh welded = weld_positions(soup);
  EXPECT_EQ(welded.positions.size(), 4u);  // -0 and +0 are one position
  EXPECT_EQ(welded.triangles[1][0], welded.triangles[0][0]);
  EXPECT_EQ(welded.triangles[1][1], welded.triangles[0][2]);
}

TEST(MeshProxy, AMeshWithoutAreaHasNoProxy) {
  TriangleMesh flat;
  flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.triangles = {{0, 1, 2}, {0, 0, 1}};
  MeshProxy proxy;
  std::string error;
  EXPECT_FALSE(make_mesh_proxy(flat, 10, proxy, error));
  EXPECT_NE(error.find("no face with a positive area"), std::string::npos) << error;
  GeometryImageOptions options;
  options.size = 16;
  options.proxy_above = 1;
  GeometryImage image;
  ParameterizedMesh pm;
  GeometryImageReport report;
  error.clear();
  EXPECT_FALSE(build_geometry_image(flat, options, image, pm, report, error));
  EXPECT_NE(error.find("no face with a positive area"), std::string::npos) << error;
  // The command: one line naming the file, exit 2, nothing written.
  const std::string base =
      std::string(gfield::build_paths::test_tmp()) + "/flat-" + std::to_string(::getpid());
  std::ofstream(base + ".obj") << "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n";
  const test::CliRun run =
      test::run_cli("build " + base + ".obj -o " + base + "-asset --proxy-above 1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find(base + ".obj: no face with a positive area"), std::string::npos)
      << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(std::filesystem::exists(base + "-asset.report.json"));
  EXPECT_FALSE(std::filesystem::exists(base + "-asset.gimage.exr"));
  std::filesystem::remove(base + ".obj");
}

/// The bunny's image at 256^2 with the proxy above `proxy_above` faces (0: never).
void bunny_image(size_t proxy_above, GeometryImage& image, GeometryImageReport& report) {
  GeometryImageOptions options;
  options.size = 256;
  options.proxy_above = proxy_above;
  ParameterizedMesh pm;
  std::string error;
  ASSERT_TRUE(
      build_geometry_image(bundled("stanford-bunny.obj"), options, image, pm, report, error))
      << error;
}

TEST(GeometryImageProxy, TexelsLieOnTheFullSurfaceAndMatchItsOwnImage) {
  GeometryImage image, full_image;
  GeometryImageReport report, full;
  bunny_image(20000, image, report);
  bunny_image(0, full_image, full);
  ASSERT_TRUE(report.proxy.used);
  EXPECT_LE(report.proxy.faces, 10000u);
  EXPECT_FALSE(full.proxy.used);
  EXPECT_EQ(full.proxy.faces, 0u);
  // Exact distances of the covered texels to the bunny: on it, but for the texels of the faces
  // that fill its holes (they keep the proxy's points).
  const TriangleMesh bunny = bundled("stanford-bunny.obj");
  EmbreeMesh embree;
  std::string error;
  ASSERT_TRUE(embree.build(bunny, error)) << error;
  std::vector<glm::dvec3> texels;
  for (size_t t = 0; t < image.coverage.size(); ++t)
    if (image.coverage[t] > 0.0f)
      texels.push_back(glm::dvec3(image.position[t]));
  const std::vector<ClosestPoint> closest = closest_points(embree, bunny, texels);
  size_t on = 0;
  for (const ClosestPoint& c : closest)
    on += c.distance <= 1e-6 * report.diagonal;  // float positions
  EXPECT_GE(double(on) / double(texels.size()), 0.98) << on << " of " << texels.size();
  // As close to the mesh as the full mesh's own image at the same size.
  EXPECT_LE(report.mesh_to_image.mean, 1.25 * full.mesh_to_image.mean);
  EXPECT_LE(report.image_to_mesh.mean, 1.25 * full.image_to_mesh.mean);
}

/// One mesh's geometry image built with `options` (its proxy_above) and without a proxy.
struct ProxyAndFull {
  GeometryImage image, full_image;
  ParameterizedMesh pm, full_pm;
  GeometryImageReport report, full;
};

void build_with_and_without_proxy(const TriangleMesh& mesh, GeometryImageOptions options,
                                  ProxyAndFull& out) {
  std::string error;
  ASSERT_TRUE(build_geometry_image(mesh, options, out.image, out.pm, out.report, error)) << error;
  options.proxy_above = 0;
  ASSERT_TRUE(build_geometry_image(mesh, options, out.full_image, out.full_pm, out.full, error))
      << error;
}

TEST(GeometryImageProxy, AProxyMissingTheBoundGivesWayToTheFullMesh) {
  const TriangleMesh homer = bundled("homer.obj");
  GeometryImageOptions options;
  options.max_mean_error = 1e-9;  // no image reaches it: the proxy's is rejected
  options.proxy_above = 6000;
  ProxyAndFull b;
  ASSERT_NO_FATAL_FAILURE(build_with_and_without_proxy(homer, options, b));
  EXPECT_FALSE(b.report.proxy.used);
  EXPECT_GT(b.report.proxy.faces, 0u);
  EXPECT_GT(b.report.proxy.mean_percent, 2.0 * options.max_mean_error);
  EXPECT_NE(b.report.proxy.rejected.find("exceeds"), std::string::npos) << b.report.proxy.rejected;
  EXPECT_EQ(b.pm.mesh.triangles.size(), homer.triangles.size());
  EXPECT_TRUE(b.image.position == b.full_image.position);
  EXPECT_TRUE(b.image.normal == b.full_image.normal);
}

TEST(GeometryImageProxy, AProxyWhoseRouteFailsGivesWayToTheFullMesh) {
  // The torus simplified towards 8 faces collapses to no area: the proxy route's error, which a
  // full build does not give.
  const TriangleMesh torus = bundled("torus.obj");
  GeometryImageOptions options;
  options.size = 64;
  options.proxy_above = 16;
  ProxyAndFull b;
  ASSERT_NO_FATAL_FAILURE(build_with_and_without_proxy(torus, options, b));
  EXPECT_FALSE(b.report.proxy.used);
  const std::string& rejected = b.report.proxy.rejected;
  EXPECT_EQ(rejected.rfind("its route failed: ", 0), 0u) << rejected;
  EXPECT_NE(rejected.find("no face with a positive area"), std::string::npos) << rejected;
  EXPECT_EQ(b.pm.mesh.triangles.size(), torus.triangles.size());
  EXPECT_TRUE(b.image.position == b.full_image.position);
}

TEST(GeometryImageProxy, AFlatTessellatedMeshChartsItsProxyWithoutHoles) {
  // Collapses on the flat faces of a midpoint-subdivided mesh leave needles with collinear
  // corners; unflipped, repair drops them and opens a hole per needle, and the charts' maps
  // stretch around the holes.
  GeometryImageOptions options;
  options.size = 256;
  options.proxy_above = 20000;
  ProxyAndFull b;
  ASSERT_NO_FATAL_FAILURE(
      build_with_and_without_proxy(test::midpoint_subdivided(bundled("spot.obj"), 2), options, b));
  ASSERT_TRUE(b.report.proxy.used) << b.report.proxy.rejected;
  EXPECT_GT(b.report.proxy.flat_flips, 0u);
  EXPECT_EQ(b.report.repair.degenerate_faces, 0u);
  EXPECT_EQ(b.report.repair.holes_found, b.full.repair.holes_found);
  // Within the factor an automatic size accepts (unflipped: 55 times the full mesh's image's).
  EXPECT_LE(b.report.mesh_to_image.mean, kProxyErrorFactor * b.full.mesh_to_image.mean);
}

/// `gfield build homer.obj` at 256^2, N = 12, with --proxy-above `proxy_above`: its report.
nlohmann::json homer_asset(const std::string& proxy_above, std::string& summary) {
  const std::string name =
      std::string(gfield::build_paths::test_tmp()) + "/proxy-homer-" + std::to_string(::getpid());
  const test::CliRun run = test::run_cli("build " + std::string(gfield::build_paths::mesh_dir()) +
                                         "/homer.obj -o " + name + " --proxy-above " + proxy_above +
                                         " --size 256 --samples 12 --verify-rays 5000");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  summary = run.out;
  std::ifstream file(name + ".report.json");
  const nlohmann::json report = nlohmann::json::parse(file, nullptr, false);
  for (const char* extension : {".gimage.exr", ".gimage.obj", ".gfield.exr", ".report.json"})
    std::filesystem::remove(name + extension);
  return report;
}

TEST(GeometryImageProxy, VerifyCastsTheRaysLeavingTheSurfaceFromTheOriginal) {
  std::string summary, full_summary;
  const nlohmann::json report = homer_asset("6000", summary);
  const nlohmann::json full = homer_asset("0", full_summary);
  ASSERT_TRUE(report.is_object() && full.is_object());
  EXPECT_NE(summary.find("proxy of "), std::string::npos) << summary;
  EXPECT_TRUE(report["geometry_image"]["proxy"]["used"].get<bool>());
  const nlohmann::json& accuracy = report["accuracy"];
  EXPECT_TRUE(accuracy["proxy"].get<bool>());
  ASSERT_EQ(accuracy["references"].size(), 2u);
  const nlohmann::json &built = accuracy["references"][0], &original = accuracy["references"][1];
  EXPECT_EQ(original["mesh"], "original");
  EXPECT_FALSE(built.contains("surface_rays_k1"));  // the proxy is not the surface described
  // Against the original, as the full mesh's own asset does against the mesh it was built from.
  const nlohmann::json& own = full["accuracy"]["references"][0];
  for (const char* family :
       {"box_rays", "view_rays", "surface_rays_k1", "surface_rays_k8", "mirror_rays_k1",
        "mirror_rays_k8", "glass_rays_k1", "glass_rays_k8"}) {
    ASSERT_TRUE(own.contains(family) && original.contains(family)) << family;
    EXPECT_GE(original[family]["refined"]["hit_agreement"].get<double>(),
              own[family]["refined"]["hit_agreement"].get<double>() - 0.01)
        << family;
  }
}

}  // namespace
}  // namespace gfield
