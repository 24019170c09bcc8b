// Meshes of every size and place that the readers accept: a build either makes a
// field that sees the mesh or is refused naming why (float casts lost spot 5e-12 across in a
// crash, 2.6e-15 across in a field without hits that verify called 100% right), and verify
// refuses a field that cannot see its mesh.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include <nlohmann/json.hpp>

#include "gfield/exr_io.hpp"
#include "gfield/field_lines.hpp"
#include "gfield/geometry_field.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

const fs::path kDir = test::process_folder("mesh_scale");
const std::string kFast = " --size 96 --samples 8 --verify-rays 4000";

class MeshScale : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(kDir); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(kDir, ec);
  }
  /// spot.obj with every vertex v written as v * scale + (offset, 0, 0).
  static std::string spot_moved(const std::string& name, double scale, double offset) {
    std::ifstream in(std::string(gfield::build_paths::mesh_dir()) + "/spot.obj");
    const std::string path = (kDir / (name + ".obj")).string();
    std::ofstream out(path);
    out.precision(17);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("v ", 0) == 0) {
        std::istringstream v(line.substr(2));
        double x = 0, y = 0, z = 0;
        v >> x >> y >> z;
        out << "v " << x * scale + offset << " " << y * scale << " " << z * scale << "\n";
      } else {
        out << line << "\n";
      }
    }
    return path;
  }
};

TEST_F(MeshScale, TooSmallTooLargeOrTooFarIsRefusedNamingWhy) {
  struct Case {
    const char* name;
    double scale, offset;
    const char* says;
  };
  for (const Case& c : {Case{"tiny", 1e-12, 0.0, "2.59e-12 units across"},
                        Case{"tinier", 1e-30, 0.0, "2.59e-30 units across"},
                        Case{"huge", 1e14, 0.0, "2.59e+14 units across"},
                        Case{"far", 1.0, 1e3, "1e+03 from the origin"}}) {
    const std::string mesh = spot_moved(c.name, c.scale, c.offset);
    EXPECT_EQ(run_cli("info " + mesh).exit_code, 0) << c.name << ": the readers accept it";
    for (const std::string& command :
         {"build " + mesh + " -o " + (kDir / c.name).string() + kFast,
          "image " + mesh + " -o " + (kDir / c.name).string() + ".gimage.exr --size 64"}) {
      const test::CliRun r = run_cli(command);
      EXPECT_EQ(r.exit_code, 2) << command;
      EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(mesh), std::string::npos) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(kDir / (std::string(c.name) + ".gfield.exr"))) << c.name;
    EXPECT_FALSE(fs::exists(kDir / (std::string(c.name) + ".gimage.exr"))) << c.name;
  }
}

TEST_F(MeshScale, TheEdgesOfTheRangeBuildFieldsThatSeeTheMesh) {
  // Inside the documented range, near its ends: the same agreement as spot at scale 1.
  for (const auto& [name, scale, offset] :
       {std::tuple{"small", 1e-9, 0.0}, std::tuple{"large", 3e11, 0.0},
        std::tuple{"off-centre", 1.0, 200.0}, std::tuple{"unit", 1.0, 0.0}}) {
    const std::string mesh = spot_moved(name, scale, offset);
    const test::CliRun r = run_cli("build " + mesh + " -o " + (kDir / name).string() + kFast);
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    std::ifstream in((kDir / name).string() + ".report.json");
    const nlohmann::json report = nlohmann::json::parse(in);
    const nlohmann::json& table = report["accuracy"]["references"][0]["table"];
    EXPECT_GT(table["answer_hits"].get<double>(), 0.3 * table["rays"].get<double>()) << name;
    EXPECT_GT(
        report["accuracy"]["references"][0]["box_rays"]["refined"]["hit_agreement"].get<double>(),
        0.97)
        << name;
  }
}

TEST_F(MeshScale, VerifyRefusesAFieldWithoutHitsWhereTheMeshHasSurface) {
  const std::string asset = (kDir / "spot").string();
  ASSERT_EQ(run_cli("build " + std::string(gfield::build_paths::mesh_dir()) + "/spot.obj -o " +
                    asset + kFast)
                .exit_code,
            0);
  EXPECT_EQ(run_cli("verify " + asset + " --rays 1000").exit_code, 0);
  GeometryField field;
  std::string error;
  ASSERT_TRUE(load_geometry_field(asset + ".gfield.exr", field, error)) << error;
  for (glm::vec2& uv : field.nearest)
    uv = glm::vec2(kFieldMiss);
  std::vector<TableLine> none;
  pack_line_table(none, field);
  const std::string published = fs::canonical(asset + ".gfield.exr").string();
  ASSERT_TRUE(save_geometry_field(published, field, ExrPrecision::kHalf, error)) << error;
  const test::CliRun r = run_cli("verify " + asset + " --rays 1000");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("the field has no hit where exact casts hit the mesh"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace gfield
