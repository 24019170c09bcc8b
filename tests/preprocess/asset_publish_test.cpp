// Publishing an asset is one rename (preprocess/asset_staging.hpp): every call that
// changes a folder during `gfield build`, failed (EPERM: an immutable or busy target) or killed
// (SIGKILL) in turn by a preloaded shim (tests/fault/fault_shim.c), leaves the whole old asset or
// the whole new one, for an asset of the linked layout and for one of the older layout (four
// plain files); what a killed build left is removed by the next cleaner.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "preprocess/asset_files.hpp"
#include "preprocess/asset_staging.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = test::process_folder("asset_publish");
// An octahedron: a build takes a few hundredths of a second, so that the test's 2 x 40 faulty
// builds take seconds (minutes under the sanitizers with spot).
const std::string kMesh = (kDir / "octahedron.obj").string();
const std::string kOld = " --size 16 --samples 4 --verify-rays 0";
const std::string kNew = " --size 16 --samples 6 --verify-rays 0";

std::string asset() {
  return (kDir / "out" / "spot").string();
}

/// The build id of the complete asset in kDir/out, or "" (with `why`) when it is not complete.
std::string complete_asset_id(std::string& why) {
  std::string id;
  if (!read_report_build_id(asset() + ".report.json", id, why))
    return "";
  return asset_is_build(asset_files(asset()), id, why) ? id : "";
}

/// `gfield build` of the new options with the shim making call `call` fail or kill (`mode`),
/// or counting the calls into `count_file` when `call` is 0. Returns the raw wait status.
int faulty_build(const std::string& mode, int call, const std::string& count_file = "") {
  const std::string env = "LD_PRELOAD=" + std::string(gfield::build_paths::fault_shim()) +
                          " GFIELD_FAULT=" + mode + " GFIELD_FAULT_CALL=" + std::to_string(call) +
                          (count_file.empty() ? "" : " GFIELD_FAULT_COUNT=" + count_file);
  const std::string command = env + " " + std::string(gfield::build_paths::cli()) + " build " +
                              kMesh + " -o " + asset() + kNew + " > /dev/null 2> " +
                              (kDir / "stderr.txt").string();
  return std::system(command.c_str());
}

/// Entries of the asset's builds folder that no reader reaches (left by a killed build).
std::vector<std::string> unreachable() {
  const fs::path builds = builds_folder(asset());
  std::error_code ec;
  const std::string current = fs::read_symlink(builds / "current", ec).string();
  std::vector<std::string> out;
  for (const fs::directory_entry& e : fs::directory_iterator(builds, ec)) {
    const std::string file = e.path().filename().string();
    if (file != ".lock" && file != "current" && file != current)
      out.push_back(file);
  }
  return out;
}

class AssetPublish : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    fs::remove_all(kDir);
    fs::create_directories(kDir / "out");
    std::ofstream(kMesh) << "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                            "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\n"
                            "f 1 4 6\n";
    const test::CliRun r = test::run_cli("build " + kMesh + " -o " + asset() + kOld);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    if (GetParam()) {  // the older layout: four plain files, no builds folder
      for (const fs::path file : {".gimage.exr", ".gimage.obj", ".gfield.exr", ".report.json"}) {
        const fs::path path = asset() + file.string();
        fs::copy_file(fs::canonical(path), kDir / "plain");
        fs::rename(kDir / "plain", path);
      }
      fs::remove_all(builds_folder(asset()));
    }
    std::string why;
    old_id_ = complete_asset_id(why);
    ASSERT_FALSE(old_id_.empty()) << why;
    fs::copy(kDir / "out", kDir / "pristine",
             fs::copy_options::recursive | fs::copy_options::copy_symlinks);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(kDir, ec);
  }
  void restore() {
    fs::remove_all(kDir / "out");
    fs::copy(kDir / "pristine", kDir / "out",
             fs::copy_options::recursive | fs::copy_options::copy_symlinks);
  }
  std::string old_id_;
};

TEST_P(AssetPublish, EveryStepFailedOrKilledLeavesTheWholeOldOrTheWholeNewAsset) {
  const std::string count_file = (kDir / "count.txt").string();
  ASSERT_EQ(faulty_build("none", 0, count_file), 0);
  std::string why;
  const std::string new_id = complete_asset_id(why);
  ASSERT_FALSE(new_id.empty()) << why;
  ASSERT_NE(new_id, old_id_);
  int calls = 0;
  std::ifstream(count_file) >> calls;
  ASSERT_GE(calls, 8) << "the build changes folders fewer times than a publish needs";
  int old_seen = 0, new_seen = 0;
  for (const std::string mode : {"fail", "kill"}) {
    for (int call = 1; call <= calls; ++call) {
      restore();
      const int status = faulty_build(mode, call);
      const std::string id = complete_asset_id(why);
      const std::string where = mode + " at call " + std::to_string(call) + ": ";
      ASSERT_TRUE(id == old_id_ || id == new_id) << where << (id.empty() ? why : "id " + id);
      (id == old_id_ ? old_seen : new_seen) += 1;
      if (mode == "fail") {  // exit 0 exactly when the new asset is published
        ASSERT_TRUE(WIFEXITED(status)) << where;
        EXPECT_EQ(WEXITSTATUS(status) == 0, id == new_id) << where << WEXITSTATUS(status);
      } else {
        EXPECT_TRUE(WIFSIGNALED(status) || WIFEXITED(status)) << where;
      }
      remove_stale_staging((kDir / "out").string());
      EXPECT_EQ(unreachable(), std::vector<std::string>()) << where;
    }
  }
  EXPECT_GT(old_seen, 0);
  EXPECT_GT(new_seen, 0);
}

INSTANTIATE_TEST_SUITE_P(Layouts, AssetPublish, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "OlderPlainFiles" : "LinkedBuilds";
                         });

}  // namespace
}  // namespace gfield
