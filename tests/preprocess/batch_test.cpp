// `gfield batch` as one task of a sharded, resumable batch: the shards partition the
// meshes, up to date means "the files carry the build id of the current inputs" (never file
// times), manifests and --summary, and bad input that leaves nothing behind.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

const fs::path kDir = test::process_folder("batch");
const std::string kMeshes = gfield::build_paths::mesh_dir();
const std::string kFast = " --size 64 --samples 4 --verify-rays 0";

class Batch : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::remove_all(kDir);
    fs::create_directories(kDir / "in");
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(kDir, ec);
  }
  static std::string in() { return (kDir / "in").string(); }
  static std::string out() { return (kDir / "out").string(); }
  static void copy_mesh(const std::string& stem) {
    fs::copy_file(kMeshes + "/" + stem + ".obj", kDir / "in" / (stem + ".obj"));
  }
  /// The statuses of the meshes of one run's manifest lines, by mesh file name.
  static std::map<std::string, std::string> statuses(const std::string& manifest, size_t skip) {
    std::ifstream file(manifest);
    std::map<std::string, std::string> out;
    size_t n = 0;
    for (std::string line; std::getline(file, line);) {
      if (n++ < skip) {
        continue;
      }
      const nlohmann::json r = nlohmann::json::parse(line);
      out[fs::path(r["mesh"].get<std::string>()).filename().string()] = r["status"];
    }
    return out;
  }
};

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    out.push_back(line);
  }
  return out;
}

TEST_F(Batch, ShardsPartitionTheMeshesExactlyOnce) {
  // A folder of its own (what lies beside the bundled meshes, e.g. the demo's assets, must not
  // matter): seven meshes and, beside spot, the assets a build leaves, which are not meshes.
  const std::set<std::string> meshes = {"alligator.obj", "beetle.obj", "cow.obj",  "spot.obj",
                                        "suzanne.obj",   "teapot.obj", "woody.obj"};
  for (const std::string& file : meshes)
    copy_mesh(fs::path(file).stem().string());
  fs::copy_file(kMeshes + "/spot.obj", kDir / "in" / "spot.gimage.obj");
  { std::ofstream(kDir / "in" / "spot.report.json") << "{}"; }
  for (int n : {1, 3, 4, 5}) {
    std::multiset<std::string> seen;
    for (int i = 0; i < n; ++i) {
      const test::CliRun r = run_cli("batch " + in() + " -o " + out() + " --list --shard " +
                                     std::to_string(i) + "/" + std::to_string(n) + kFast);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      for (const std::string& line : lines(r.out)) {
        seen.insert(fs::path(line.substr(0, line.find(" -> "))).filename().string());
      }
    }
    EXPECT_EQ(seen.size(), meshes.size()) << n;
    EXPECT_EQ(std::set<std::string>(seen.begin(), seen.end()), meshes) << n;
  }
  EXPECT_FALSE(fs::exists(out())) << "--list writes nothing";
}

TEST_F(Batch, UpToDateByContentNotByFileTimes) {
  copy_mesh("suzanne");
  copy_mesh("woody");
  const std::string manifest = out() + "/manifest-0-of-1.jsonl";
  const std::string args = "batch " + in() + " -o " + out() + kFast;
  ASSERT_EQ(run_cli(args).exit_code, 0);
  using M = std::map<std::string, std::string>;
  EXPECT_EQ(statuses(manifest, 0), (M{{"suzanne.obj", "built"}, {"woody.obj", "built"}}));
  // A newer mesh file with the same bytes (a copy, a checkout, a skewed clock): up to date.
  fs::last_write_time(in() + "/suzanne.obj",
                      fs::file_time_type::clock::now() + std::chrono::hours(1));
  ASSERT_EQ(run_cli(args).exit_code, 0);
  EXPECT_EQ(statuses(manifest, 2), (M{{"suzanne.obj", "up to date"}, {"woody.obj", "up to date"}}));
  // New bytes with an older time: rebuilt.
  { std::ofstream(in() + "/woody.obj", std::ios::app) << "# edited\n"; }
  fs::last_write_time(in() + "/woody.obj",
                      fs::file_time_type::clock::now() - std::chrono::hours(24));
  ASSERT_EQ(run_cli(args).exit_code, 0);
  EXPECT_EQ(statuses(manifest, 4), (M{{"suzanne.obj", "up to date"}, {"woody.obj", "built"}}));
  // A texture named by the OBJ's material library: appearing, then changing, rebuilds.
  { std::ofstream(in() + "/suzanne.obj", std::ios::app) << "mtllib suzanne.mtl\n"; }
  ASSERT_EQ(run_cli(args).exit_code, 0);
  { std::ofstream(in() + "/suzanne.mtl") << "newmtl skin\nmap_Kd skin.png\n"; }
  ASSERT_EQ(run_cli(args).exit_code, 0);
  EXPECT_EQ(statuses(manifest, 8), (M{{"suzanne.obj", "built"}, {"woody.obj", "up to date"}}));
  { std::ofstream(in() + "/skin.png") << "pixels"; }
  ASSERT_EQ(run_cli(args).exit_code, 0);
  EXPECT_EQ(statuses(manifest, 10), (M{{"suzanne.obj", "built"}, {"woody.obj", "up to date"}}));
  ASSERT_EQ(run_cli(args).exit_code, 0);
  EXPECT_EQ(statuses(manifest, 12),
            (M{{"suzanne.obj", "up to date"}, {"woody.obj", "up to date"}}));
  // Another output-changing option: both rebuilt; a missing file: that asset rebuilt.
  ASSERT_EQ(run_cli(args + " --float").exit_code, 0);
  EXPECT_EQ(statuses(manifest, 14), (M{{"suzanne.obj", "built"}, {"woody.obj", "built"}}));
  fs::remove(out() + "/woody.gimage.obj");
  ASSERT_EQ(run_cli(args + " --float").exit_code, 0);
  EXPECT_EQ(statuses(manifest, 16), (M{{"suzanne.obj", "up to date"}, {"woody.obj", "built"}}));
}

TEST_F(Batch, ManifestAndSummaryNameFailuresAndTheShardsToRerun) {
  copy_mesh("woody");
  copy_mesh("suzanne");
  { std::ofstream(in() + "/broken.obj") << "v 0 0 0\nv 1 0 0\n"; }  // no faces
  // Shard 0 of 2 holds broken and woody; shard 1 (suzanne) has not run yet.
  test::CliRun r = run_cli("batch " + in() + " -o " + out() + " --shard 0/2" + kFast);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("1 of 2 meshes failed"), std::string::npos) << r.err;
  std::ifstream manifest(out() + "/manifest-0-of-2.jsonl");
  std::string line;
  ASSERT_TRUE(std::getline(manifest, line));
  const nlohmann::json failed = nlohmann::json::parse(line);
  EXPECT_EQ(failed["status"], "failed");
  EXPECT_NE(failed["error"].get<std::string>().find("broken.obj"), std::string::npos);
  EXPECT_EQ(failed["shard"], "0/2");
  EXPECT_EQ(failed["meshes"], 3);
  ASSERT_TRUE(std::getline(manifest, line));
  const nlohmann::json built = nlohmann::json::parse(line);
  EXPECT_EQ(built["status"], "built");
  EXPECT_EQ(built["outputs"].size(), 4u);
  EXPECT_GT(built["seconds"].get<double>(), 0.0);

  r = run_cli("batch --summary " + out());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("3 meshes: 1 built, 0 up to date, 1 failed, 1 without a line"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("no faces"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rerun shards 0,1 of 2"), std::string::npos) << r.out;
  // Shard 1 runs, the broken mesh is fixed and shard 0 rerun: woody is up to date, all is well.
  ASSERT_EQ(run_cli("batch " + in() + " -o " + out() + " --shard 1/2" + kFast).exit_code, 0);
  fs::copy_file(kMeshes + "/spot.obj", in() + "/broken.obj", fs::copy_options::overwrite_existing);
  ASSERT_EQ(run_cli("batch " + in() + " -o " + out() + " --shard 0/2" + kFast).exit_code, 0);
  r = run_cli("batch --summary " + out());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("3 meshes: 2 built, 1 up to date, 0 failed, 0 without a line"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("slowest:"), std::string::npos) << r.out;
}

TEST_F(Batch, AMeshThatLeavesTheInputBetweenShardsIsListedAndTheSummaryConverges) {
  copy_mesh("woody");
  copy_mesh("suzanne");
  copy_mesh("cow");
  ASSERT_EQ(run_cli("batch " + in() + " -o " + out() + " --shard 0/2" + kFast).exit_code, 0);
  fs::remove(in() + "/cow.obj");  // gone before shard 1 runs
  ASSERT_EQ(run_cli("batch " + in() + " -o " + out() + " --shard 1/2" + kFast).exit_code, 0);
  test::CliRun r = run_cli("batch --summary " + out());
  for (int rerun = 0; r.exit_code == 2 && rerun < 2; ++rerun) {  // what the summary asks for
    const size_t at = r.out.find("rerun shards ");
    ASSERT_NE(at, std::string::npos) << r.out;
    for (const char* shard : {"0", "1"})
      if (r.out.substr(at, 20).find(shard) != std::string::npos)
        ASSERT_EQ(run_cli("batch " + in() + " -o " + out() + " --shard " + shard + "/2" + kFast)
                      .exit_code,
                  0);
    r = run_cli("batch --summary " + out());
  }
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("2 meshes: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("meshes gone from the input since their lines:\n  " + in() + "/cow.obj"),
            std::string::npos)
      << r.out;
}

TEST_F(Batch, BadInputIsOneLineAndWritesNothing) {
  copy_mesh("woody");
  fs::copy_file(kMeshes + "/woody.obj", kDir / "woody.obj");
  { std::ofstream(kDir / "a-file") << "x"; }
  const std::string inputs = "batch " + in() + " " + kFast;
  const std::pair<std::string, std::string> cases[] = {
      {inputs + " -o " + out() + " --shard 2/2", "0 <= I < N"},
      {inputs + " -o " + out() + " --shard -1/2", "0 <= I < N"},
      {inputs + " -o " + out() + " --shard 0/0", "N >= 1"},
      {inputs + " -o " + out() + " --shard a/b", "expected I/N"},
      {inputs + " -o " + out() + " --shard 3", "expected I/N"},
      {"batch " + (kDir / "missing").string() + " -o " + out() + kFast, "missing: no such"},
      {inputs + " " + (kDir / "woody.obj").string() + " -o " + out(), "would both build"},
      {inputs + " -o " + (kDir / "a-file" / "out").string(), "cannot create the output folder"},
      {inputs + " -o /proc", "/proc: the output folder is not writable"},
      {"batch --summary " + in(), "no manifest"},
  };
  for (const auto& [args, message] : cases) {
    const test::CliRun r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(out()));
}

}  // namespace
}  // namespace gfield
