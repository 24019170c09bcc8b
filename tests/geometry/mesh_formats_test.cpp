// The mesh-format table (geometry/mesh_formats.hpp): extensions found in any case, every row's
// reader wired (a seed of its fuzz target loads through load_mesh), one fuzz target per row, the
// lists the helps print, and the side files of the formats that name some.

#include "geometry/mesh_formats.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "geometry/mesh_io.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(gfield::build_paths::test_tmp()) / "mesh_formats";

void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

TEST(MeshFormats, ExtensionsAreFoundInAnyCaseAndListedForTheHelps) {
  std::set<std::string_view> extensions;
  for (const MeshFormat& format : mesh_formats()) {
    EXPECT_TRUE(extensions.insert(format.extension).second) << format.extension;
    EXPECT_EQ(find_mesh_format("a/b/Mesh" + std::string(format.extension)), &format);
  }
  EXPECT_EQ(find_mesh_format("spot.OBJ"), find_mesh_format("spot.obj"));
  EXPECT_EQ(find_mesh_format("spot.GlB")->extension, ".glb");
  EXPECT_EQ(find_mesh_format("spot.obj.txt"), nullptr);
  EXPECT_EQ(find_mesh_format("obj"), nullptr);
  EXPECT_EQ(mesh_extension_list(), ".obj, .ply, .off, .stl, .gltf, .glb");
  EXPECT_EQ(batch_extension_list(), ".obj, .ply, .off, .stl");
  EXPECT_TRUE(is_gltf_file("scene.GLTF"));
  EXPECT_FALSE(is_gltf_file("spot.obj"));
}

// tests/fuzz/CMakeLists.txt makes a reader target per folder corpus/mesh_EXT: there is one for
// every format and no other, and the regressions have a folder each.
TEST(MeshFormats, EveryFormatHasAFuzzTargetWithSeedsThatLoad) {
  const fs::path fuzz(gfield::build_paths::fuzz_dir());
  std::set<std::string> formats, corpora;
  for (const MeshFormat& format : mesh_formats()) {
    const std::string target = "mesh_" + std::string(format.extension.substr(1));
    formats.insert(target);
    EXPECT_TRUE(fs::is_directory(fuzz / "regressions" / target)) << target;
    int loaded = 0;
    for (const fs::directory_entry& seed : fs::directory_iterator(fuzz / "corpus" / target)) {
      const fs::path copy = kDir / target / ("seed" + std::string(format.extension));
      fs::create_directories(copy.parent_path());
      fs::copy_file(seed.path(), copy, fs::copy_options::overwrite_existing);
      TriangleMesh mesh;
      std::string error;
      loaded += load_mesh(copy.string(), mesh, error) ? 1 : 0;
    }
    EXPECT_GT(loaded, 0) << target << ": no seed loads through its row's reader";
  }
  for (const fs::directory_entry& entry : fs::directory_iterator(fuzz / "corpus")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("mesh_", 0) == 0)
      corpora.insert(name);
  }
  EXPECT_EQ(corpora, formats);
}

TEST(MeshFormats, SideFilesAreWhatTheMeshNamesInItsFolder) {
  const fs::path dir = kDir / "side";
  write_file(dir / "a.obj", "mtllib a.mtl missing.mtl ../outside.mtl\nv 0 0 0\n");
  write_file(dir / "a.mtl", "newmtl m\nmap_Kd tex/a.png\nbump b.png\nKd 1 1 1\n");
  write_file(dir / "p.ply", "ply\nformat ascii 1.0\ncomment TextureFile t.png\nend_header\n");
  write_file(dir / "o.off", "OFF\n0 0 0\n");
  const auto names = [&](const std::vector<std::string>& files) {
    std::vector<std::string> out;
    for (const std::string& f : files)
      out.push_back(fs::path(f).lexically_relative(dir).generic_string());
    return out;
  };
  const std::vector<std::string> obj = {"a.mtl", "tex/a.png", "b.png", "missing.mtl"};
  EXPECT_EQ(names(mesh_side_files((dir / "a.obj").string(), OutsidePaths::kRefused)), obj);
  EXPECT_EQ(names(mesh_side_files((dir / "a.obj").string(), OutsidePaths::kAllowed)).back(),
            "../outside.mtl");
  EXPECT_EQ(names(mesh_side_files((dir / "p.ply").string(), OutsidePaths::kRefused)),
            std::vector<std::string>{"t.png"});
  EXPECT_TRUE(mesh_side_files((dir / "o.off").string(), OutsidePaths::kRefused).empty());
  EXPECT_TRUE(mesh_side_files((dir / "a.txt").string(), OutsidePaths::kRefused).empty());
}

}  // namespace
}  // namespace gfield
