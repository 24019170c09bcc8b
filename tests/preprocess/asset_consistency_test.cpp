// An asset is one consistent unit: `gfield build` stamps one build id on all
// four files and publishes them together; verify, thickness and the loaders refuse a set of two
// builds naming both files; a killed build leaves the old asset or the new one, and its build
// folder is removed by the next run; concurrent builders end with one complete asset.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "geometry/parameterized_mesh.hpp"
#include "gfield/content_hash.hpp"
#include "gfield/exr_io.hpp"
#include "preprocess/asset_files.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/republishing.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

const fs::path kDir = test::process_folder("asset_unit");
const std::string kSpot = std::string(gfield::build_paths::mesh_dir()) + "/spot.obj";
const std::string kCow = std::string(gfield::build_paths::mesh_dir()) + "/cow.obj";
const std::string kSmall = " --size 128 --samples 4 --verify-rays 500";
const std::string kLarger = " --size 192 --samples 6 --verify-rays 500";

class AssetUnit : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::remove_all(kDir);
    fs::create_directories(kDir);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(kDir, ec);
  }
  static std::string name(const std::string& stem) { return (kDir / stem).string(); }
  static void build(const std::string& mesh, const std::string& stem, const std::string& opts) {
    const test::CliRun r = run_cli("build " + mesh + " -o " + name(stem) + opts);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static std::string report_id(const std::string& stem) {
    std::ifstream in(name(stem) + ".report.json");
    return nlohmann::json::parse(in)["build_id"].get<std::string>();
  }
  /// A build's leftovers: temporaries in kDir, and in the assets' builds folders every folder or
  /// link but the lock, `current` and the folder it names.
  static std::vector<std::string> leftovers() {
    std::vector<std::string> out;
    for (const fs::directory_entry& e : fs::directory_iterator(kDir)) {
      const std::string file = e.path().filename().string();
      if (file.find(".tmp-") != std::string::npos) {
        out.push_back(file);
      } else if (e.path().extension() == ".builds") {
        std::error_code ec;
        const std::string current = fs::read_symlink(e.path() / "current", ec).string();
        for (const fs::directory_entry& b : fs::directory_iterator(e.path())) {
          const std::string name = b.path().filename().string();
          if (name != ".lock" && name != "current" && name != current) {
            out.push_back(file + "/" + name);
          }
        }
      }
    }
    return out;
  }
};

/// Starts `gfield ARGS...` (stdout and stderr to /dev/null); returns its pid.
pid_t spawn(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    std::vector<char*> argv{const_cast<char*>(gfield::build_paths::cli())};
    for (const std::string& a : args) {
      argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    execv(gfield::build_paths::cli(), argv.data());
    _exit(127);
  }
  return pid;
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string t; in >> t;) {
    out.push_back(t);
  }
  return out;
}

TEST_F(AssetUnit, BuildStampsOneIdOnAllFourFiles) {
  build(kSpot, "spot", kSmall);
  const std::string id = report_id("spot");
  EXPECT_EQ(id.size(), 32u);
  std::string why;
  EXPECT_TRUE(asset_is_build(asset_files(name("spot")), id, why)) << why;
  std::ifstream in(name("spot") + ".report.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  std::string mesh_hash;
  std::string error;
  ASSERT_TRUE(sha256_file(kSpot, mesh_hash, error)) << error;
  EXPECT_EQ(report["inputs"]["mesh"]["sha256"], mesh_hash);
  EXPECT_EQ(report["inputs"]["options"]["samples_per_side"], 4);
  // Other options, another id; the same options again, the same id.
  build(kSpot, "spot", kLarger);
  EXPECT_NE(report_id("spot"), id);
  build(kSpot, "spot", kSmall);
  EXPECT_EQ(report_id("spot"), id);
  EXPECT_TRUE(leftovers().empty());
}

TEST_F(AssetUnit, VerifyAndThicknessRefuseFilesOfTwoBuilds) {
  build(kSpot, "old", kSmall);
  build(kSpot, "new", kLarger);
  // What an interrupted rebuild with new options could leave before build ids: the new 192^2
  // image beside the old N = 4 field and report (verify then exited 0 with a 10x table error).
  fs::copy_file(name("new") + ".gimage.exr", name("old") + ".gimage.exr",
                fs::copy_options::overwrite_existing);
  test::CliRun r = run_cli("verify " + name("old") + " --rays 200");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("old.gimage.obj"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("old.gimage.exr"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("two different builds"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  r = run_cli("thickness " + name("old"));
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("two different builds"), std::string::npos) << r.err;
  // With the new mesh too, the field is the odd one out.
  fs::copy_file(name("new") + ".gimage.obj", name("old") + ".gimage.obj",
                fs::copy_options::overwrite_existing);
  r = run_cli("verify " + name("old") + " --rays 200");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("old.gfield.exr: does not match"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("old.gimage.exr"), std::string::npos) << r.err;
  // With the new field as well, only the report is stale.
  fs::copy_file(name("new") + ".gfield.exr", name("old") + ".gfield.exr",
                fs::copy_options::overwrite_existing);
  r = run_cli("verify " + name("old") + " --rays 200");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("old.report.json: build id"), std::string::npos) << r.err;
  fs::copy_file(name("new") + ".report.json", name("old") + ".report.json",
                fs::copy_options::overwrite_existing);
  r = run_cli("verify " + name("old") + " --rays 200");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(AssetUnit, StaleReportOfAnotherMeshIsNotUsed) {
  build(kSpot, "spot", kSmall);
  build(kCow, "cow", kSmall);
  // The report of the cow over spot's asset: its source_path would make verify compare spot's
  // field against cow.obj.
  fs::copy_file(name("cow") + ".report.json", name("spot") + ".report.json",
                fs::copy_options::overwrite_existing);
  test::CliRun r = run_cli("verify " + name("spot") + " --rays 200");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("spot.report.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("spot.gimage.exr"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("cow.obj"), std::string::npos) << r.out;
}

TEST_F(AssetUnit, VerifyJudgesAgainstTheAssetsOwnMeshNotAPathTakenFromItsReport) {
  build(kSpot, "spot", kSmall);
  // The report of spot's own build, its source_path pointed at another mesh.
  nlohmann::json report;
  std::ifstream(name("spot") + ".report.json") >> report;
  report["source_path"] = kCow;
  std::ofstream(name("spot") + ".report.json") << report.dump();
  const test::CliRun r = run_cli("verify " + name("spot") + " --rays 200");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_EQ(r.err.rfind("gfield: error: " + name("spot") + ".report.json: built from spot.obj", 0),
            0u)
      << r.err;
  EXPECT_NE(r.err.find("not from " + kCow), std::string::npos) << r.err;
  const test::CliRun given = run_cli("verify " + name("spot") + " --rays 200 --original " + kSpot);
  EXPECT_EQ(given.exit_code, 0) << given.err;
}

TEST_F(AssetUnit, VersionOneAssetsWithoutIdsStillLoad) {
  build(kSpot, "spot", kSmall);
  GeometryImage image;
  GeometryField field;
  ParameterizedMesh pm;
  std::string error;
  const AssetFiles files = asset_files(name("spot"));
  ASSERT_TRUE(load_geometry_image(files.image, image, error)) << error;
  ASSERT_TRUE(load_geometry_field(files.field, field, error)) << error;
  ASSERT_TRUE(load_parameterized_mesh(files.parameterized_mesh, pm, error)) << error;
  image.build_id.clear();
  field.build_id.clear();
  pm.build_id.clear();
  ASSERT_TRUE(save_geometry_image(files.image, image, ExrPrecision::kFloat, error)) << error;
  ASSERT_TRUE(save_geometry_field(files.field, field, ExrPrecision::kHalf, error)) << error;
  ASSERT_TRUE(save_parameterized_mesh(files.parameterized_mesh, pm, error)) << error;
  fs::remove(files.report);
  test::CliRun r = run_cli("verify " + name("spot") + " --rays 200 --original " + kSpot);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(run_cli("thickness " + name("spot")).exit_code, 0);
}

TEST_F(AssetUnit, KilledRebuildLeavesTheOldAssetOrTheNewOne) {
  build(kSpot, "spot", kSmall);
  const std::string old_id = report_id("spot");
  bool saw_staging = false;
  // SIGKILL a rebuild with other options at increasing delays: the asset is the whole old build
  // or the whole new one (the publish is one rename; asset_publish_test.cpp kills every step).
  for (int delay_ms : {100, 250, 400, 600, 900, 1400}) {
    const pid_t pid = spawn(split("build " + kSpot + " -o " + name("spot") + kLarger));
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
    saw_staging = saw_staging || !leftovers().empty();
    const test::CliRun r = run_cli("verify " + name("spot") + " --rays 200 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json report = nlohmann::json::parse(r.out);
    const bool is_old = report["image_size"] == 128 && report["samples_per_side"] == 4;
    const bool is_new = report["image_size"] == 192 && report["samples_per_side"] == 6;
    EXPECT_TRUE(is_old || is_new) << r.out.substr(0, 300);
    EXPECT_EQ(report_id("spot") == old_id, is_old);
    if (is_new) {
      build(kSpot, "spot", kSmall);  // back to the old options for the next round
    }
  }
  EXPECT_TRUE(saw_staging) << "no kill landed inside a build: raise the delays' range";
  // The next build removes what the killed ones left.
  build(kSpot, "spot", kSmall);
  EXPECT_TRUE(leftovers().empty()) << leftovers().front();
  EXPECT_EQ(report_id("spot"), old_id);
}

TEST_F(AssetUnit, AVerifyWhileTheAssetIsRepublishedReadsOneBuild) {
  build(kSpot, "spot", kSmall);
  // Republish two builds of other options in turn, 8 times, while verifies run.
  std::string failure;
  const int failed = test::failed_reads_while_republishing(
      [&](int round) {
        const pid_t pid =
            spawn(split("build " + kSpot + " -o " + name("spot") + (round % 2 ? kLarger : kSmall)));
        waitpid(pid, nullptr, 0);
      },
      [&] { return run_cli("verify " + name("spot") + " --rays 100"); }, 8, failure);
  EXPECT_EQ(failed, 0) << failure;
}

TEST_F(AssetUnit, InterruptedBuildLeavesNothingBehind) {
  build(kSpot, "spot", kSmall);
  const pid_t pid = spawn(split("build " + kSpot + " -o " + name("spot") + kLarger));
  // Wait until the build writes into its staging folder, then Ctrl-C it.
  for (int i = 0; i < 400 && leftovers().empty(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) {
    EXPECT_TRUE(leftovers().empty()) << leftovers().front();
  }
  std::string why;
  const bool old_or_new = asset_is_build(asset_files(name("spot")), report_id("spot"), why);
  EXPECT_TRUE(old_or_new) << why;
}

TEST_F(AssetUnit, ConcurrentBuildersEndWithOneCompleteAsset) {
  // Two builders of one asset with different options, started together, twice.
  for (int round = 0; round < 2; ++round) {
    const pid_t a = spawn(split("build " + kSpot + " -o " + name("spot") + kSmall));
    const pid_t b = spawn(split("build " + kSpot + " -o " + name("spot") + kLarger));
    int status_a = 0;
    int status_b = 0;
    waitpid(a, &status_a, 0);
    waitpid(b, &status_b, 0);
    EXPECT_TRUE(WIFEXITED(status_a) && WEXITSTATUS(status_a) == 0);
    EXPECT_TRUE(WIFEXITED(status_b) && WEXITSTATUS(status_b) == 0);
    std::string why;
    EXPECT_TRUE(asset_is_build(asset_files(name("spot")), report_id("spot"), why)) << why;
    EXPECT_EQ(run_cli("verify " + name("spot") + " --rays 200").exit_code, 0);
    EXPECT_TRUE(leftovers().empty());
  }
}

}  // namespace
}  // namespace gfield
