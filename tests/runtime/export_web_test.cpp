// gfield export-web (preprocess/cli/export_web.cpp): gfield runs gfield-view's export, passes on
// its options, prints the folder's size, and passes on gfield-view's refusal (its line, its exit
// code, no folder); a gfield-view that cannot be run, or that a signal kills, is one line of
// gfield's, exit code 2.
// The page drawing the export: web/test/player.test.mjs.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir =
      fs::path(gfield::build_paths::test_tmp()) / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(ExportWeb, GfieldRunsTheViewersExportAndPassesTheSizeOn) {
  const fs::path out = fresh_dir("export_web");
  const std::string scene =
      std::string(gfield::build_paths::data_dir()) + "/scenes/two-mirror-spheres.json";
  const test::CliRun run =
      test::run_cli("export-web " + scene + " -o " + out.string() + " --size 96x64");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("wrote " + out.string() + ": "), std::string::npos) << run.out;
  EXPECT_TRUE(fs::is_regular_file(out / "index.html"));
  EXPECT_TRUE(fs::is_regular_file(out / "scene.bin.gz"));
  std::ifstream manifest(out / "scene.json");
  EXPECT_EQ(nlohmann::json::parse(manifest).at("size"), nlohmann::json({96, 64}))
      << "--size reached gfield-view";
  fs::remove_all(out);
}

TEST(ExportWeb, ARefusalIsTheViewersLineAndExitCodeAndNoFolder) {
  const fs::path out = fresh_dir("export_web_refused");
  const test::CliRun missing = test::run_cli("export-web no-such-scene.json -o " + out.string());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no-such-scene.json"), std::string::npos) << missing.err;
  EXPECT_EQ(missing.err.find("gfield: error"), std::string::npos) << "one line, gfield-view's";
  EXPECT_FALSE(fs::exists(out));
  const std::string scene =
      std::string(gfield::build_paths::data_dir()) + "/scenes/two-mirror-spheres.json";
  // gfield export-web of the scene with $GFIELD_VIEW set to `viewer`.
  const auto export_with = [&](const std::string& viewer) {
    return test::run_program("GFIELD_VIEW=" + viewer + " " + gfield::build_paths::cli(),
                             "export-web " + scene + " -o " + out.string());
  };
  const test::CliRun no_viewer = export_with("/nonexistent/gfield-view");
  EXPECT_EQ(no_viewer.exit_code, 2);
  EXPECT_NE(no_viewer.err.find("gfield: error: /nonexistent/gfield-view: cannot be run"),
            std::string::npos)
      << no_viewer.err;
  EXPECT_FALSE(fs::exists(out));
  // A gfield-view that dies by a signal has said nothing: gfield says it.
  const fs::path killed = fresh_dir("export_web_killed");
  fs::create_directories(killed);
  std::ofstream(killed / "gfield-view") << "#!/bin/sh\nkill -9 $$\n";
  fs::permissions(killed / "gfield-view", fs::perms::owner_all);
  const test::CliRun signalled = export_with((killed / "gfield-view").string());
  EXPECT_EQ(signalled.exit_code, 2);
  EXPECT_NE(signalled.err.find("gfield-view: killed by signal 9 (nothing was exported)"),
            std::string::npos)
      << signalled.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(killed);
}

}  // namespace
}  // namespace gfield
