// End-to-end: the `gfield` executable on good and bad input (exit codes, one-line errors).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"

namespace {

using gfield::test::CliRun;
using gfield::test::run_cli;

TEST(CliInfo, PrintsTheTopologyOfSpot) {
  const CliRun run = run_cli(std::string("info ") + gfield::build_paths::mesh_dir() + "/spot.obj");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("closed, genus 0 (sphere)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("5856 triangles"), std::string::npos) << run.out;
}

TEST(CliInfo, JsonOutputParses) {
  const CliRun run =
      run_cli(std::string("info --json ") + gfield::build_paths::mesh_dir() + "/rocker-arm.obj");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);
  EXPECT_EQ(j["components"][0]["genus"], 1);
  EXPECT_EQ(j["faces"], 20088);
}

TEST(CliInfo, BadInputExitsWithCodeTwoAndOneLine) {
  const std::string tmp = gfield::build_paths::test_tmp();
  std::ofstream(tmp + "/cli_empty.obj").close();
  std::ofstream(tmp + "/cli_range.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n";
  for (const std::string& file : {tmp + "/cli_missing.obj", tmp + "/cli_empty.obj",
                                  tmp + "/cli_range.obj", tmp + "/cli_mesh.unknown"}) {
    const CliRun run = run_cli("info " + file);
    EXPECT_EQ(run.exit_code, 2) << file;
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_NE(run.err.find(file), std::string::npos) << run.err;
  }
  const CliRun no_args = run_cli("info");
  EXPECT_EQ(no_args.exit_code, 2);
  const CliRun help = run_cli("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("info"), std::string::npos);
}

TEST(CliInfo, AnUnknownCommandIsNamed) {
  const CliRun run = run_cli("NOSUCH data.obj");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.rfind("gfield: NOSUCH: no such command (the commands: info, ", 0), 0u)
      << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
}

TEST(CliInfo, AnAssetNameThatIsAFolderOrHiddenIsRefusedAndNothingWritten) {
  const std::string dir = std::string(gfield::build_paths::test_tmp()) + "/cli_asset_names";
  for (const std::string& name : {dir + "/", dir + "/.hidden", dir + "/."}) {
    const CliRun run = run_cli(std::string("build ") + gfield::build_paths::mesh_dir() +
                               "/woody.obj -o " + name + " --size 32");
    EXPECT_EQ(run.exit_code, 2) << name;
    EXPECT_EQ(run.err, "gfield: error: " + name +
                           ": expected DIR/NAME, the name the asset's files begin with "
                           "(NAME.gimage.exr, ...): not a folder, and not beginning with '.'\n");
  }
  EXPECT_FALSE(std::filesystem::exists(dir));
}

}  // namespace
