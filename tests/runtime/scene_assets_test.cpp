// gfield-view draws a mesh's asset only when it was built from that mesh as it is now
// (runtime/scene_assets.hpp): the torus's asset under spot's name and spot's asset after spot.obj
// changed are refused naming both files (exit 2), or rebuilt with --rebuild-stale; an asset
// file that is there but cannot be read is an error naming it, not a silent fall back to the BVH.

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/republishing.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {
namespace fs = std::filesystem;

const fs::path kDir = test::process_folder("scene_assets");
const char* kFiles[] = {".gimage.exr", ".gimage.obj", ".gfield.exr", ".report.json"};

class SceneAssets : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fs::remove_all(kDir);
    fs::create_directories(kDir / "built");
    for (const char* mesh : {"spot", "torus"}) {
      const test::CliRun run = test::run_cli(
          std::string("build " + std::string(gfield::build_paths::mesh_dir()) + "/") + mesh +
          ".obj -o " + (kDir / "built" / mesh).string() + " --size 64 --samples 4 --verify-rays 0");
      ASSERT_EQ(run.exit_code, 0) << run.err;
    }
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(kDir, ec);
  }
  void SetUp() override {
    fs::remove_all(kDir / "case");
    fs::create_directories(kDir / "case" / "assets");
    fs::copy_file(std::string(gfield::build_paths::mesh_dir()) + "/spot.obj",
                  kDir / "case" / "spot.obj");
    std::ofstream(kDir / "case" / "scene.json") << R"({
      "camera": {"position": [0, 0.5, 3], "target": [0, 0, 0], "fov": 40},
      "image": {"width": 32, "height": 32}, "environment": {"type": "studio"},
      "objects": [{"name": "spot", "shape": "mesh", "file": "spot.obj",
                   "material": {"type": "mirror"}}]})";
  }
  /// Copies the built asset of `mesh` into the case's asset folder as spot's.
  static void use_asset_of(const std::string& mesh) {
    for (const char* file : kFiles)
      fs::copy_file(kDir / "built" / (mesh + file),
                    kDir / "case" / "assets" / ("spot" + std::string(file)),
                    fs::copy_options::overwrite_existing);
  }
  static test::CliRun view(const std::string& extra = "") {
    return test::run_program(gfield::build_paths::view(),
                             (kDir / "case" / "scene.json").string() + " --assets " +
                                 (kDir / "case" / "assets").string() +
                                 " --headless --bench --size 16x16 " + extra);
  }
  static std::string report() { return (kDir / "case" / "assets" / "spot.report.json").string(); }
};

TEST_F(SceneAssets, TheMeshsOwnAssetIsDrawnByItsField) {
  use_asset_of("spot");
  const test::CliRun r = view();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("meshes by field: spot.obj; by BVH: none"), std::string::npos) << r.out;
}

TEST_F(SceneAssets, AnotherMeshsAssetIsRefusedNamingBothFiles) {
  use_asset_of("torus");
  const test::CliRun r = view();
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("gfield-view: " + report() + ": built from torus.obj (", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("not from " + (kDir / "case" / "spot.obj").string()), std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(SceneAssets, AStaleAssetIsRefusedOrRebuiltOnRequest) {
  use_asset_of("spot");
  std::ofstream(kDir / "case" / "spot.obj", std::ios::app) << "# edited\n";
  const test::CliRun refused = view();
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("built from spot.obj"), std::string::npos) << refused.err;
  const test::CliRun rebuilt = view("--rebuild-stale");
  ASSERT_EQ(rebuilt.exit_code, 0) << rebuilt.err;
  EXPECT_NE(rebuilt.err.find("rebuilding"), std::string::npos) << rebuilt.err;
  EXPECT_NE(rebuilt.out.find("meshes by field: spot.obj"), std::string::npos) << rebuilt.out;
  EXPECT_EQ(view().exit_code, 0) << "the rebuilt asset is the mesh's";
}

TEST_F(SceneAssets, AnAssetFileThatCannotBeReadIsNamedNotSkipped) {
  use_asset_of("spot");
  const fs::path field = kDir / "case" / "assets" / "spot.gfield.exr";
  fs::remove(field);
  ASSERT_EQ(::mkfifo(field.c_str(), 0644), 0);
  test::CliRun r = view();
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "gfield-view: " + field.string() + ": a FIFO, not a regular file\n");
  fs::remove(field);
  fs::create_directory_symlink("/nonexistent-folder", field);
  r = view();
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "gfield-view: " + field.string() + ": a dangling symbolic link\n");
}

TEST_F(SceneAssets, AViewWhileTheAssetIsRepublishedReadsOneBuild) {
  // The asset published in the case's folder (linked layout), republished 16 times with two sizes
  // in turn while views run: each view draws one build, never files of two.
  const std::string spot = (kDir / "case" / "spot.obj").string();
  const std::string name = (kDir / "case" / "assets" / "spot").string();
  const auto publish = [&](int round) {
    return test::run_cli("build " + spot + " -o " + name + " --samples 4 --verify-rays 0 --size " +
                         (round % 2 ? "64" : "96"));
  };
  ASSERT_EQ(publish(0).exit_code, 0);
  std::string failure;
  const int failed = test::failed_reads_while_republishing(
      [&](int round) { publish(round); }, [&] { return view("--method field"); }, 16, failure);
  EXPECT_EQ(failed, 0) << failure;
}

}  // namespace
}  // namespace gfield
