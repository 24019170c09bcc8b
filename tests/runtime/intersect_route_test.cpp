// --intersect auto (runtime/methods/intersect_route.hpp): the cost model's routes at the sizes
// bench_runtime_complexity measured, and gfield-view tracing each mesh the way it says (the
// example's mirror torus by its BVH, its glass spot by its field: alone, each the same picture
// as that route's) and saying why.

#include "runtime/methods/intersect_route.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"

namespace gfield {
namespace {
namespace fs = std::filesystem;

TEST(IntersectRoute, TheModelPicksWhatTheBenchmarkMeasuredFaster) {
  // bench_runtime_complexity's tracing pass on llvmpipe: glass faster by its field at every size
  // it measured, 5.9K to 1.1M faces; mirrors by their BVHs up to 278K faces, and at 1.1M as fast
  // as by the field within the runs' spread.
  for (size_t faces : {5856u, 69451u, 277804u, 1111216u})
    EXPECT_FALSE(auto_route({faces, true, true}).bvh) << faces << " glass";
  for (size_t faces : {5856u, 69451u, 277804u})
    EXPECT_TRUE(auto_route({faces, true, false}).bvh) << faces << " mirror";
  EXPECT_FALSE(auto_route({1111216u, true, false}).bvh);
  EXPECT_EQ(auto_route({1111216u, true, false}).why, "~59 BVH nodes per mirror ray >= 53");
  EXPECT_EQ(auto_route({69451u, true, true}).why, "~68 BVH nodes per glass ray >= 49");
  // Glass crosses at about 3K faces; mirrors at about 320K, below the memory budget's 3.2M (which
  // sends a mesh to its field whatever the time).
  EXPECT_LT(estimated_bvh_nodes(2500, true), kFieldNodesGlass);
  EXPECT_GE(estimated_bvh_nodes(3500, true), kFieldNodesGlass);
  EXPECT_TRUE(auto_route({2500u, true, true}).bvh);
  EXPECT_EQ(auto_route({2500u, true, true}).why, "~48 BVH nodes per glass ray < 49");
  EXPECT_LT(estimated_bvh_nodes(290000, false), kFieldNodesMirror);
  EXPECT_GE(estimated_bvh_nodes(350000, false), kFieldNodesMirror);
  EXPECT_NEAR(estimated_bvh_nodes(5856, false), 34.6, 1.0);
  EXPECT_NEAR(estimated_bvh_nodes(1111216, true), 85.2, 1.0);
}

TEST(IntersectRoute, NoFieldMeansTheBvhAndAnOversizedBvhMeansTheField) {
  const Route none = auto_route({1000u, false, false});
  EXPECT_TRUE(none.bvh);
  EXPECT_EQ(none.why, "no field");
  const Route big = auto_route({4000000u, true, true});
  EXPECT_FALSE(big.bvh);
  EXPECT_EQ(big.why, "its BVH would take 1360 MB > 1074");
}

/// A scene of `objects` (JSON) seen from above the torus, written to `file`.
void write_scene(const fs::path& file, const std::string& objects) {
  std::ofstream(file) << R"({
    "camera": {"position": [0, 1, 3.5], "target": [0, 0, 0], "fov": 40},
    "image": {"width": 48, "height": 48}, "environment": {"type": "studio"},
    "objects": [)" + objects +
                             "]}";
}

/// gfield-view's arguments for `scene` (its assets beside it), headless, up to --intersect.
std::string view_arguments(const fs::path& scene) {
  return scene.string() + " --assets " + scene.parent_path().string() +
         " --allow-outside-paths --headless --depth 4 --intersect ";
}

/// Whether gfield-view draws `scene` with --intersect auto exactly as with --intersect `route`.
void expect_auto_draws_as(const fs::path& scene, const std::string& route) {
  const std::string view = view_arguments(scene);
  const std::string base = (scene.parent_path() / scene.stem()).string();
  ASSERT_EQ(test::run_program(gfield::build_paths::view(), view + "auto -o " + base + "-auto.png")
                .exit_code,
            0);
  ASSERT_EQ(test::run_program(gfield::build_paths::view(),
                              view + route + " -o " + base + "-" + route + ".png")
                .exit_code,
            0);
  const test::CliRun same =
      test::run_cli("compare " + base + "-auto.png " + base + "-" + route + ".png");
  EXPECT_NE(same.out.find("max |a-b|       0\n"), std::string::npos) << scene << same.out;
}

TEST(IntersectRoute, TheViewerTracesEachMeshTheWayTheModelSaysAndSaysWhy) {
  const fs::path dir =
      fs::path(gfield::build_paths::test_tmp()) / ("intersect_route_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const char* mesh : {"spot", "torus"}) {
    const test::CliRun run = test::run_cli(
        std::string("build " + std::string(gfield::build_paths::mesh_dir()) + "/") + mesh +
        ".obj -o " + (dir / mesh).string() + " --size 64 --samples 4 --verify-rays 0");
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  const std::string meshes = gfield::build_paths::mesh_dir();
  const std::string torus = R"({"name": "torus", "shape": "mesh", "file": ")" + meshes +
                            R"(/torus.obj", "material": {"type": "mirror"}})";
  const std::string spot = R"({"name": "spot", "shape": "mesh", "file": ")" + meshes +
                           R"(/spot.obj", "transform": {"translate": [0.9, 0, 0], "scale": 0.5},
       "material": {"type": "dielectric", "ior": 1.5}})";
  write_scene(dir / "both.json", torus + ", " + spot);
  const test::CliRun automatic = test::run_program(
      gfield::build_paths::view(),
      view_arguments(dir / "both.json") + "auto --bench -o " + (dir / "both.png").string());
  ASSERT_EQ(automatic.exit_code, 0) << automatic.err;
  EXPECT_NE(automatic.out.find("meshes by field: spot.obj (auto: ~53 BVH nodes per glass ray >= "
                               "49); by BVH: torus.obj (auto: ~37 BVH nodes per mirror ray < 53)"),
            std::string::npos)
      << automatic.out;
  write_scene(dir / "torus.json", torus);
  expect_auto_draws_as(dir / "torus.json", "bvh");
  write_scene(dir / "spot.json", spot);
  expect_auto_draws_as(dir / "spot.json", "field");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gfield
