// NAME.report.json as a struct: a real build's report and `gfield verify`'s report read back
// give the same JSON again (every section's from_json the inverse of its to_json), and a file
// that is not an asset report is refused with one line naming the file and what is wrong.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gfield/asset_source.hpp"
#include "preprocess/asset_build.hpp"
#include "preprocess/asset_report.hpp"
#include "preprocess/verify.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = test::process_folder("asset_report");

/// Spot built once (small, with its accuracy) for every test here; its report's JSON as written.
class AssetReportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fs::remove_all(kDir);
    AssetOptions options;
    options.image.size = 64;
    options.samples_per_side = 6;
    options.verify_rays = 2000;
    size_t stale = 0;
    std::string error;
    const std::string mesh = std::string(gfield::build_paths::mesh_dir()) + "/spot.obj";
    built_ = new AssetReport;
    ASSERT_TRUE(build_asset_at(mesh, name(), options, *built_, stale, error)) << error;
    std::ifstream(name() + ".report.json") >> written_;
  }
  static void TearDownTestSuite() {
    delete built_;
    fs::remove_all(kDir);
  }
  static std::string name() { return (kDir / "spot").string(); }
  /// Writes `j` as a report file beside the asset and reads it; the error ("" when read).
  static std::string read_back(const nlohmann::json& j) {
    const std::string file = (kDir / "other.report.json").string();
    std::ofstream(file) << j.dump(2);
    AssetReport report;
    std::string error;
    return read_asset_report(file, report, error) ? "" : error;
  }
  static AssetReport* built_;
  static nlohmann::json written_;
};

AssetReport* AssetReportTest::built_ = nullptr;
nlohmann::json AssetReportTest::written_;

TEST_F(AssetReportTest, TheWrittenReportIsTheBuildsReport) {
  EXPECT_EQ(asset_report_to_json(*built_), written_);
  ASSERT_TRUE(built_->accuracy.has_value());
  EXPECT_EQ(built_->accuracy->references.size(), 2u);  // the built mesh and spot.obj
  BuiltMesh mesh;
  ASSERT_TRUE(built_mesh_from_inputs(built_->inputs, mesh));
  EXPECT_EQ(mesh.file, "spot.obj");
  EXPECT_EQ(mesh.bytes, fs::file_size(std::string(build_paths::mesh_dir()) + "/spot.obj"));
}

TEST_F(AssetReportTest, ReadingAndWritingAgainGivesTheSameJson) {
  AssetReport read;
  std::string error;
  ASSERT_TRUE(read_asset_report(name() + ".report.json", read, error)) << error;
  EXPECT_EQ(asset_report_to_json(read), written_);
  EXPECT_EQ(read.build_id, built_->build_id);
  EXPECT_EQ(read.image_size, 64);
  EXPECT_EQ(read.geometry_field.samples_per_side, 6);
  EXPECT_EQ(read.topology.faces, built_->topology.faces);
  EXPECT_EQ(read.accuracy->described().table.agree, built_->accuracy->described().table.agree);
}

TEST_F(AssetReportTest, VerifyReportsReadBackTheSame) {
  VerifyOptions options;
  options.rays = 1000;
  VerifyReport report;
  std::string error;
  ASSERT_TRUE(verify_asset(name(), options, report, error)) << error;
  const nlohmann::json j = verify_report_to_json(report);
  EXPECT_EQ(verify_report_to_json(verify_report_from_json(j)), j);
  EXPECT_EQ(verify_report_to_text(verify_report_from_json(j)), verify_report_to_text(report));
  EXPECT_GT(report.described().families.at("box_rays").at("refined").hit_agreement(), 0.9);
}

TEST_F(AssetReportTest, WhatIsNotAnAssetReportIsNamed) {
  nlohmann::json no_id = written_;
  no_id.erase("build_id");
  const std::string file = (kDir / "other.report.json").string();
  EXPECT_EQ(read_back(no_id), file + ": not an asset report (key 'build_id' not found)");
  nlohmann::json wrong_type = written_;
  wrong_type["geometry_field"]["layers"] = "eight";
  EXPECT_EQ(read_back(wrong_type).rfind(file + ": not an asset report (type must be number", 0), 0u)
      << read_back(wrong_type);
  nlohmann::json no_mesh = written_;
  no_mesh["inputs"].erase("mesh");
  EXPECT_EQ(read_back(no_mesh),
            file + ": not an asset report (no record of its mesh (inputs.mesh))");
  EXPECT_EQ(read_back(nlohmann::json::array()), file + ": not a JSON object");
  EXPECT_EQ(read_back(written_), "");
}

}  // namespace
}  // namespace gfield
