// --intersect auto (runtime/methods/intersect_route.hpp): the cost model's routes at the sizes
// bench_runtime_complexity measured, and gfield-view tracing each mesh the way it says (the
// example meshes by their BVHs: the same picture as --intersect bvh) and saying why.

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
  // bench_runtime_complexity on llvmpipe: mirrors and glass faster by their BVH at every size it
  // measured, 5.9K to 1.1M faces.
  for (size_t faces : {5856u, 69451u, 277804u, 1111216u}) {
    EXPECT_TRUE(auto_route({faces, true, true}).bvh) << faces << " glass";
    EXPECT_TRUE(auto_route({faces, true, false}).bvh) << faces << " mirror";
  }
  EXPECT_EQ(auto_route({1111216u, true, false}).why, "~59 BVH nodes per mirror ray < 65");
  EXPECT_EQ(auto_route({69451u, true, true}).why, "~68 BVH nodes per glass ray < 88");
  // Glass crosses at about 1.8M faces, below the memory budget's 3.2M (which sends a mesh to its
  // field whatever the time); mirrors would cross at about 4.4M, beyond it.
  EXPECT_LT(estimated_bvh_nodes(1500000, true), kFieldNodesGlass);
  EXPECT_GE(estimated_bvh_nodes(2500000, true), kFieldNodesGlass);
  EXPECT_FALSE(auto_route({2500000u, true, true}).bvh);
  EXPECT_EQ(auto_route({2500000u, true, true}).why, "~90 BVH nodes per glass ray >= 88");
  EXPECT_LT(estimated_bvh_nodes(4000000, false), kFieldNodesMirror);
  EXPECT_GE(estimated_bvh_nodes(5000000, false), kFieldNodesMirror);
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
  std::ofstream(dir / "scene.json")
      << R"({
    "camera": {"position": [0, 1, 3.5], "target": [0, 0, 0], "fov": 40},
    "image": {"width": 48, "height": 48}, "environment": {"type": "studio"},
    "objects": [
      {"name": "torus", "shape": "mesh", "file": ")" +
             std::string(gfield::build_paths::mesh_dir()) + R"(/torus.obj",
       "material": {"type": "mirror"}},
      {"name": "spot", "shape": "mesh", "file": ")" +
             std::string(gfield::build_paths::mesh_dir()) + R"(/spot.obj",
       "transform": {"translate": [0.9, 0, 0], "scale": 0.5},
       "material": {"type": "dielectric", "ior": 1.5}}]})";
  const std::string view = (dir / "scene.json").string() + " --assets " + dir.string() +
                           " --allow-outside-paths --headless --depth 4 --intersect ";
  const test::CliRun automatic = test::run_program(
      gfield::build_paths::view(), view + "auto --bench -o " + (dir / "auto.png").string());
  ASSERT_EQ(automatic.exit_code, 0) << automatic.err;
  EXPECT_NE(automatic.out.find("meshes by field: none; by BVH: torus.obj (auto: ~37 BVH nodes "
                               "per mirror ray < 65), spot.obj (auto: ~53 BVH nodes per glass "
                               "ray < 88)"),
            std::string::npos)
      << automatic.out;
  ASSERT_EQ(
      test::run_program(gfield::build_paths::view(), view + "bvh -o " + (dir / "bvh.png").string())
          .exit_code,
      0);
  const test::CliRun same =
      test::run_cli("compare " + (dir / "auto.png").string() + " " + (dir / "bvh.png").string());
  EXPECT_NE(same.out.find("max |a-b|       0\n"), std::string::npos) << same.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gfield
