// Damaged and absurd inputs through the gfield commands: every one exits with code 2,
// prints one line on stderr that names the file, nothing on stdout, and leaves no output file.
// The damaged files themselves are tests/fuzz/regressions/* (README.md there says which case of
// the issue each is); the cases that need a whole asset are made here from a small build.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geometry/parameterized_mesh.hpp"
#include "gfield/exr_io.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/refusal.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::expect_refused;
using test::run_cli;
using test::run_program;

const fs::path kRegressions = fs::path(gfield::build_paths::fuzz_dir()) / "regressions";
const fs::path kDir = test::process_folder("hardened");

/// `text` in single quotes for the shell (file names may hold any byte but NUL).
std::string quote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return out + "'";
}

std::vector<fs::path> files_in(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool empty_folder(const fs::path& folder) {
  return !fs::exists(folder) || fs::is_empty(folder);
}

/// A copy of the good asset (made by the suite's set-up) in a folder of its own: DIR/tet.*.
fs::path copy_asset(const std::string& name) {
  const fs::path dir = kDir / name;
  fs::create_directories(dir);
  for (const fs::path& f : files_in(kDir / "good")) {  // the files, not the links to them
    if (!fs::is_directory(f))
      fs::copy_file(fs::canonical(f), dir / f.filename(), fs::copy_options::overwrite_existing);
  }
  return dir;
}

class HardenedInputs : public ::testing::Test {
 protected:
  /// A small asset (the tetrahedron seed at 8^2, N = 4) that the asset cases damage copies of.
  static void SetUpTestSuite() {
    fs::remove_all(kDir);
    fs::create_directories(kDir / "good");
    const std::string mesh =
        (fs::path(gfield::build_paths::fuzz_dir()) / "corpus/mesh_obj/tetrahedron.obj");
    const CliRun r = run_cli("build " + mesh + " -o " + (kDir / "good/tet").string() +
                             " --size 8 --samples 4 --verify-rays 0");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ready_ = true;
  }
  void SetUp() override { ASSERT_TRUE(ready_) << "the test suite's set-up failed (see above)"; }
  static void TearDownTestSuite() { fs::remove_all(kDir); }

  static inline bool ready_ = false;
};

TEST_F(HardenedInputs, DamagedMeshFilesAreRefusedByInfoAndBuild) {
  for (const char* format : {"mesh_obj", "mesh_ply", "mesh_off", "mesh_stl"}) {
    for (const fs::path& file : files_in(kRegressions / format)) {
      expect_refused(run_cli("info " + file.string()), {file.string()}, "info");
      const fs::path out = kDir / "build-out";
      expect_refused(run_cli("build " + file.string() + " -o " + (out / "x").string()),
                     {file.string()}, "build");
      EXPECT_TRUE(empty_folder(out)) << file << ": build left files behind";
      fs::remove_all(out);
    }
  }
}

TEST_F(HardenedInputs, ABuildOutOfMemorySaysWhereAndWhatItNeedsAndWritesNothing) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than any limit leaves";
#else
  // 130 MB of address space: the executable and its libraries fit, a geometry image of spot
  // does not. `timeout`: an allocation failure must end the build, not hang it.
  const fs::path out = kDir / "oom-out";
  const CliRun run =
      run_program("ulimit -v 130000; exec timeout 120 " + std::string(gfield::build_paths::cli()),
                  "build " + std::string(gfield::build_paths::mesh_dir()) + "/spot.obj -o " +
                      (out / "spot").string() + " --verify-rays 0");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err.rfind("gfield: error: " + std::string(gfield::build_paths::mesh_dir()) +
                              "/spot.obj: out of memory while ",
                          0),
            0u)
      << run.err;
  EXPECT_NE(run.err.find("a build of its 5856 triangles needs about"), std::string::npos)
      << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(fs::exists(out / "spot.report.json"));
  EXPECT_FALSE(fs::exists(out / "spot.gimage.exr"));
#endif
}

TEST_F(HardenedInputs, DamagedScenesAreRefusedByRender) {
  for (const fs::path& scene : files_in(kRegressions / "scene")) {
    const fs::path out = kDir / "render.png";
    expect_refused(run_cli("render " + scene.string() + " -o " + out.string() + " --size 8x8"),
                   {scene.string()}, "render");
    EXPECT_FALSE(fs::exists(out)) << scene;
  }
}

TEST_F(HardenedInputs, DamagedAssetFilesAreRefusedByVerifyAndThickness) {
  const std::pair<const char*, const char*> kinds[] = {
      {"gimage", ".gimage.exr"}, {"gfield", ".gfield.exr"}, {"gimage_obj", ".gimage.obj"}};
  for (const auto& [folder, extension] : kinds) {
    for (const fs::path& damaged : files_in(kRegressions / folder)) {
      const fs::path dir = copy_asset("damaged");
      const std::string target = (dir / "tet").string() + extension;
      fs::copy_file(damaged, target, fs::copy_options::overwrite_existing);
      expect_refused(run_cli("verify " + (dir / "tet").string() + " --rays 100"), {target},
                     damaged.string());
      if (std::string(folder) != "gfield") {
        expect_refused(run_cli("thickness " + (dir / "tet").string()), {target}, damaged.string());
        EXPECT_FALSE(fs::exists(dir / "tet.thickness.exr")) << damaged;
      }
    }
  }
}

/// Saves the good asset's geometry image with `change` applied, in a folder of its own.
template <class Change>
fs::path damaged_image(const std::string& name, Change change) {
  const fs::path dir = copy_asset(name);
  GeometryImage image;
  std::string error;
  EXPECT_TRUE(load_geometry_image((dir / "tet.gimage.exr").string(), image, error)) << error;
  change(image);
  EXPECT_TRUE(
      save_geometry_image((dir / "tet.gimage.exr").string(), image, ExrPrecision::kFloat, error))
      << error;
  return dir;
}

TEST_F(HardenedInputs, AbsurdGeometryImageValuesNeverReachEmbree) {
  // A position of 1e30 (Embree's ray assertion in verify and thickness), a NaN coverage.
  const fs::path far = damaged_image("far", [](GeometryImage& image) {
    image.position[image.position.size() / 2] = glm::vec3(1e30f, 0.0f, 0.0f);
  });
  const fs::path nan = damaged_image("nan", [](GeometryImage& image) {
    image.coverage[3] = std::numeric_limits<float>::quiet_NaN();
  });
  for (const fs::path& dir : {far, nan}) {
    const std::string file = (dir / "tet.gimage.exr").string();
    expect_refused(run_cli("verify " + (dir / "tet").string() + " --rays 100"), {file}, "verify");
    expect_refused(run_cli("thickness " + (dir / "tet").string()), {file}, "thickness");
  }
}

TEST_F(HardenedInputs, AnotherMeshsParameterisationIsRefused) {
  const fs::path dir = copy_asset("moved");
  ParameterizedMesh pm;
  std::string error;
  const std::string obj = (dir / "tet.gimage.obj").string();
  ASSERT_TRUE(load_parameterized_mesh(obj, pm, error)) << error;
  for (glm::dvec3& p : pm.mesh.positions) {
    p = 10.0 * p + 5.0;
  }
  ASSERT_TRUE(save_parameterized_mesh(obj, pm, error)) << error;
  expect_refused(run_cli("verify " + (dir / "tet").string() + " --rays 100"), {obj}, "verify");
  expect_refused(run_cli("thickness " + (dir / "tet").string()), {obj}, "thickness");
}

TEST_F(HardenedInputs, AbsurdSceneTransformsNeverReachEmbree) {
  // A mesh whose vertices are far out, scaled up (world coordinates beyond 1e15), and a mesh
  // scaled down with the camera far away (the scene beyond 1e15 in the mesh's own coordinates).
  const fs::path mesh = kDir / "far.obj";
  std::ofstream(mesh) << "v 0 0 0\nv 1e12 0 0\nv 0 1e12 0\nv 0 0 1e12\n"
                         "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
  const std::string object = R"("objects": [{"shape": "mesh", "file": "far.obj", )"
                             R"("material": {"type": "mirror"}, "transform": {"scale": )";
  const std::pair<const char*, const char*> cases[] = {
      {R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, )", "1e6}}]}"},
      {R"({"camera": {"position": [0, 0, 1e13], "target": [0, 0, 0]}, )", "1e-6}}]}"}};
  for (const auto& [camera, scale] : cases) {
    const fs::path scene = kDir / "absurd.json";
    std::ofstream(scene) << camera << object << scale << "\n";
    const fs::path out = kDir / "absurd.png";
    const CliRun run = run_cli("render " + scene.string() + " -o " + out.string() + " --size 8x8");
    expect_refused(run, {scene.string()}, scale);
    EXPECT_NE(run.err.find("objects[0]"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("far.obj"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(HardenedInputs, MeshesAtTheCoordinateLimitAreRenderedButNotMadeAssets) {
  // `gfield image` on a mesh scaled by 1e30 used to write a file gfield could not read; a mesh at
  // the coordinate limit (+-1e15) is read and rendered, and refused as an asset naming why (float
  // casts lose a surface 3.5e15 across: mesh_scale_test.cpp).
  const fs::path dir = kDir / "limit";
  fs::create_directories(dir);
  std::ofstream(dir / "big.obj") << "v -1e15 -1e15 -1e15\nv 1e15 -1e15 -1e15\nv -1e15 1e15 -1e15\n"
                                    "v -1e15 -1e15 1e15\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
  const std::string name = (dir / "big").string();
  EXPECT_EQ(run_cli("info " + name + ".obj").exit_code, 0);
  const CliRun build =
      run_cli("build " + name + ".obj -o " + name + " --size 8 --samples 4 --verify-rays 100");
  expect_refused(build, {name + ".obj"}, "build");
  EXPECT_NE(build.err.find("3.46e+15 units across"), std::string::npos) << build.err;
  std::ofstream(dir / "big.json") << R"({"camera": {"position": [0, 0, 9e14], "target": [0, 0, 0]},
    "objects": [{"shape": "mesh", "file": "big.obj", "material": {"type": "mirror"}}]})";
  const CliRun render = run_cli("render " + (dir / "big.json").string() + " -o " +
                                (dir / "big.png").string() + " --size 8x8 -q");
  EXPECT_EQ(render.exit_code, 0) << render.err;
}

TEST_F(HardenedInputs, FileNamesThatAreNotUtf8AreEscaped) {
  const fs::path dir = kDir / "names";
  fs::create_directories(dir);
  const std::string name = (dir / "caf\xE9.obj").string();
  fs::copy_file(fs::path(gfield::build_paths::fuzz_dir()) / "corpus/mesh_obj/tetrahedron.obj",
                name);
  const CliRun info = run_cli("info --json " + quote(name));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_EQ(nlohmann::json::parse(info.out)["file"], (dir / "caf\\xE9.obj").string());

  const std::string asset = (dir / "caf\xE9").string();
  const CliRun build =
      run_cli("build " + quote(name) + " -o " + quote(asset) + " --size 8 --samples 4");
  ASSERT_EQ(build.exit_code, 0) << build.err;
  std::ifstream report(asset + ".report.json");
  const nlohmann::json j = nlohmann::json::parse(report, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << "report.json is not JSON";
  EXPECT_EQ(j["mesh"], "caf\\xE9.obj");

  const std::string missing = (dir / "missing\xFF.obj").string();
  expect_refused(run_cli("info " + quote(missing)), {(dir / "missing\\xFF.obj").string()},
                 "missing file");
}

}  // namespace
}  // namespace gfield
