// Files that are not plain files, names that are not plain text, and writes the system refuses:
// a symbolic link loop, a dangling link or a FIFO given to a reader is named as such;
// `gfield batch` skips (and lists) such entries of a folder and builds the rest; names with line
// breaks or bytes that are not UTF-8 print on one line; a refused write says the system's reason.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

const fs::path kDir = test::process_folder("special_files");

class SpecialFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::remove_all(kDir);
    fs::create_directories(kDir / "in");
    fs::create_symlink("loop-b.obj", kDir / "in" / "loop-a.obj");
    fs::create_symlink("loop-a.obj", kDir / "in" / "loop-b.obj");
    fs::create_symlink("nowhere.obj", kDir / "in" / "dangling.obj");
    ASSERT_EQ(::mkfifo((kDir / "in" / "pipe.obj").c_str(), 0644), 0);
    fs::copy_file(std::string(gfield::build_paths::mesh_dir()) + "/woody.obj",
                  kDir / "in" / "woody.obj");
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(kDir, ec);
  }
  static std::string in(const std::string& file) { return (kDir / "in" / file).string(); }
};

TEST_F(SpecialFiles, ReadersNameWhatTheFileIs) {
  const std::pair<const char*, const char*> cases[] = {{"loop-a.obj", "a symbolic link loop"},
                                                       {"dangling.obj", "a dangling symbolic link"},
                                                       {"pipe.obj", "a FIFO, not a regular file"},
                                                       {"missing.obj", "no such file"}};
  for (const auto& [file, says] : cases) {
    const test::CliRun r = run_cli("info " + in(file));
    EXPECT_EQ(r.exit_code, 2) << file;
    EXPECT_EQ(r.err, "gfield: error: " + in(file) + ": " + says + "\n");
  }
  const test::CliRun r = run_cli("build " + in("loop-a.obj") + " -o " + (kDir / "x").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a symbolic link loop"), std::string::npos) << r.err;
}

TEST_F(SpecialFiles, BatchSkipsAndListsWhatIsNotAFileAndBuildsTheRest) {
  const std::string odd = "we\nird\xFF.obj";
  fs::copy_file(std::string(gfield::build_paths::mesh_dir()) + "/woody.obj", kDir / "in" / odd);
  const std::string args = "batch " + (kDir / "in").string() + " -o " + (kDir / "out").string() +
                           " --size 64 --samples 4 --verify-rays 0";
  const test::CliRun list = run_cli(args + " --list");
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_EQ(std::count(list.out.begin(), list.out.end(), '\n'), 2) << list.out;
  EXPECT_NE(list.out.find("we\\nird\\xFF.obj -> "), std::string::npos) << list.out;
  const test::CliRun r = run_cli(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* file : {"dangling.obj", "loop-a.obj", "loop-b.obj", "pipe.obj"})
    EXPECT_NE(r.err.find("gfield: warning: skipped " + in(file) + ": "), std::string::npos)
        << file << "\n"
        << r.err;
  EXPECT_EQ(r.err.find('\xFF'), std::string::npos) << "raw bytes in the progress lines";
  EXPECT_EQ(r.out.find('\xFF'), std::string::npos);
  EXPECT_TRUE(fs::exists(kDir / "out" / "woody.gfield.exr"));
  EXPECT_TRUE(fs::exists(kDir / "out" / "we\nird\xFF.gfield.exr"));
}

TEST_F(SpecialFiles, AReportThatIsAFifoOrAFolderIsNamedAndBlocksNothing) {
  const std::string asset = (kDir / "woody").string();
  const test::CliRun built = run_cli("build " + in("woody.obj") + " -o " + asset +
                                     " --size 64 --samples 4 --verify-rays 0");
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const std::string report = asset + ".report.json";
  fs::remove(report);  // the link to the published build's report
  ASSERT_EQ(::mkfifo(report.c_str(), 0644), 0);
  test::CliRun r = run_cli("verify " + asset + " --rays 100");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "gfield: error: " + report + ": a FIFO, not a regular file\n");
  fs::remove(report);
  fs::create_directory(report);
  r = run_cli("verify " + asset + " --rays 100");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "gfield: error: " + report + ": a folder, not a file\n");
}

TEST_F(SpecialFiles, ARefusedWriteSaysWhy) {
  std::ofstream(kDir / "file") << "a file, not a folder";
  const std::string target = (kDir / "file" / "out.png").string();
  const test::CliRun r = run_cli("render " + std::string(gfield::build_paths::data_dir()) +
                                 "/scenes/two-mirror-spheres.json -q "
                                 "--size 8x8 --spp 1 -o " +
                                 target);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "gfield: error: " + target + ": cannot write (Not a directory)\n");
}

}  // namespace
}  // namespace gfield
