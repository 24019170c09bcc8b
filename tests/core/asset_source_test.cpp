// An asset's report against the mesh a scene or command names (gfield/asset_source.hpp): the
// same file passes; another size, or the same size with other bytes, is refused naming both
// files; an absent report is nothing to check; a report that is not a file, or that holds no
// record of its mesh, is refused.

#include "gfield/asset_source.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gfield/content_hash.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = test::process_folder("asset_source");

class AssetSource : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::remove_all(kDir);
    fs::create_directories(kDir);
    write(mesh_, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    std::string hash, error;
    ASSERT_TRUE(sha256_file(mesh_, hash, error)) << error;
    const nlohmann::json report = {
        {"inputs", {{"mesh", {{"file", "tri.obj"}, {"bytes", 32}, {"sha256", hash}}}}}};
    write(report_, report.dump());
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(kDir, ec);
  }
  static void write(const std::string& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
  }
  const std::string mesh_ = (kDir / "tri.obj").string();
  const std::string report_ = (kDir / "tri.report.json").string();
};

TEST_F(AssetSource, TheMeshItWasBuiltFromPasses) {
  bool checked = false;
  std::string error;
  EXPECT_TRUE(check_asset_source(report_, mesh_, checked, error)) << error;
  EXPECT_TRUE(checked);
}

TEST_F(AssetSource, AnotherSizeOrOtherBytesOfTheSameSizeAreRefusedNamingBothFiles) {
  for (const char* text :
       {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# edited\n", "v 0 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\n"}) {
    write(mesh_, text);
    bool checked = false;
    std::string error;
    EXPECT_FALSE(check_asset_source(report_, mesh_, checked, error)) << text;
    EXPECT_TRUE(checked);
    EXPECT_EQ(error.rfind(report_ + ": built from tri.obj (", 0), 0u) << error;
    EXPECT_NE(error.find("not from " + mesh_), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

TEST_F(AssetSource, TheRecordedSizeAndTimeAreTakenWithoutReadingTheMesh) {
  std::int64_t modified = 0;
  ASSERT_TRUE(file_modified_ns(mesh_, modified));
  std::string error;
  nlohmann::json report;
  ASSERT_TRUE(read_report_json(report_, report, error)) << error;
  report["mesh_modified_ns"] = modified;
  write(report_, report.dump());
  // Other bytes of the same size: with the recorded time they are not read (the size and the
  // time say the file is the one hashed), with another time they are, and refused.
  const auto when = fs::last_write_time(mesh_);
  write(mesh_, "v 0 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\n");
  fs::last_write_time(mesh_, when);
  bool checked = false;
  EXPECT_TRUE(check_asset_source(report_, mesh_, checked, error)) << error;
  EXPECT_TRUE(checked);
  fs::last_write_time(mesh_, when + std::chrono::seconds(1));
  EXPECT_FALSE(check_asset_source(report_, mesh_, checked, error));
  EXPECT_NE(error.find("sha256"), std::string::npos) << error;
}

TEST_F(AssetSource, AnAbsentReportIsNothingToCheck) {
  fs::remove(report_);
  bool checked = true;
  std::string error;
  EXPECT_TRUE(check_asset_source(report_, mesh_, checked, error)) << error;
  EXPECT_FALSE(checked);
}

TEST_F(AssetSource, AReportThatIsNotAFileOrHoldsNoMeshIsRefused) {
  bool checked = false;
  std::string error;
  fs::remove(report_);
  ASSERT_EQ(::mkfifo(report_.c_str(), 0644), 0);
  EXPECT_FALSE(check_asset_source(report_, mesh_, checked, error));  // does not block
  EXPECT_EQ(error, report_ + ": a FIFO, not a regular file");
  fs::remove(report_);
  fs::create_directory(report_);
  EXPECT_FALSE(check_asset_source(report_, mesh_, checked, error));
  EXPECT_EQ(error, report_ + ": a folder, not a file");
  fs::remove(report_);
  write(report_, R"({"inputs": {}})");
  EXPECT_FALSE(check_asset_source(report_, mesh_, checked, error));
  EXPECT_NE(error.find("no record of the mesh it was built from"), std::string::npos) << error;
}

TEST_F(AssetSource, AnAssetIsCheckedByItsNameThroughItsReport) {
  // Plain files, no published builds: one read (a republish while reading is read again:
  // SceneAssets.AViewWhileTheAssetIsRepublishedReadsOneBuild).
  bool checked = false;
  std::string error;
  EXPECT_TRUE(check_asset_source_of((kDir / "tri").string(), mesh_, checked, error)) << error;
  EXPECT_TRUE(checked);
  write(report_, "{");
  EXPECT_FALSE(check_asset_source_of((kDir / "tri").string(), mesh_, checked, error));
  EXPECT_EQ(error, report_ + ": not a JSON object");
}

TEST_F(AssetSource, SceneMeshesAreCheckedThroughTheirGeometryImagesReport) {
  Scene scene;
  MeshAsset mesh;
  mesh.file = mesh_;
  mesh.geometry_image = (kDir / "tri.gimage.exr").string();
  scene.meshes.push_back(mesh);
  int stale = -2;
  std::string error;
  EXPECT_TRUE(check_scene_assets(scene, stale, error)) << error;
  EXPECT_EQ(stale, -1);
  write(mesh_, "v 0 0 0\n");
  EXPECT_FALSE(check_scene_assets(scene, stale, error));
  EXPECT_EQ(stale, 0);
  EXPECT_EQ(asset_report_path("a/b.gimage.exr"), "a/b.report.json");
  EXPECT_EQ(asset_report_path("a/b.exr"), "");
}

}  // namespace
}  // namespace gfield
