// The files an input names stay in its folder (a JSON scene's: its root) unless
// outside paths are allowed (gfield/confined_path.hpp).

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "gfield/confined_path.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = test::process_folder("confined");

/// resolve_named_path from `base` inside `root`, refused: its problem ("" when it was allowed).
std::string refusal(const fs::path& base, const std::string& name, const fs::path& root) {
  std::string resolved, problem;
  return resolve_named_path(base, name, root, OutsidePaths::kRefused, resolved, problem) ? ""
                                                                                         : problem;
}

TEST(ConfinedPath, InsideByWholeComponentsAndCanonicalPaths) {
  fs::create_directories(kDir / "a/b");
  fs::create_directories(kDir / "a/bc");
  std::error_code ec;
  fs::create_symlink("../bc", kDir / "a/b/out", ec);
  const fs::path root = kDir / "a/b";
  EXPECT_EQ(refusal(root, "x.obj", root), "");
  EXPECT_EQ(refusal(root, "./deeper/../x.obj", root), "");
  EXPECT_NE(refusal(root, "../bc/x.obj", root).find("leaves " + fs::canonical(root).string()),
            std::string::npos);  // a sibling whose name starts with the root's
  EXPECT_NE(refusal(root, "out/x.obj", root).find("leaves"), std::string::npos);  // a link out
  EXPECT_NE(refusal(root, "/etc/passwd", root).find("\"/etc/passwd\" is an absolute path"),
            std::string::npos);
  std::string resolved, problem;
  EXPECT_TRUE(
      resolve_named_path(root, "../bc/x.obj", root, OutsidePaths::kAllowed, resolved, problem));
  EXPECT_EQ(resolved, (kDir / "a/bc/x.obj").string());
  EXPECT_TRUE(path_is_inside(root, kDir / "a/b/c/d"));
  EXPECT_FALSE(path_is_inside(root, kDir / "a/bc"));
  fs::remove_all(kDir);
}

TEST(ConfinedPath, ABareFileNamesFolderIsTheWorkingFolder) {
  // A glTF file named without a folder ("m.gltf"): its folder is "", which must confine as "."
  // does; an empty root would hold every path.
  EXPECT_NE(refusal("", "../../etc/passwd", "").find("leaves " + fs::current_path().string()),
            std::string::npos);
  EXPECT_EQ(refusal("", "x.bin", ""), "");
}

TEST(ConfinedPath, SceneRootIsTheNearestFolderWithTheMarker) {
  fs::create_directories(kDir / "project/scenes/more");
  EXPECT_EQ(scene_root((kDir / "project/scenes/more/s.json").string()),
            fs::canonical(kDir / "project/scenes/more"));
  std::ofstream(kDir / "project" / kPathRootMarker) << "";
  EXPECT_EQ(scene_root((kDir / "project/scenes/more/s.json").string()),
            fs::canonical(kDir / "project"));
  // The example scenes' root is data/, which holds their meshes.
  EXPECT_EQ(
      scene_root(std::string(gfield::build_paths::data_dir()) + "/scenes/two-mirror-spheres.json"),
      fs::canonical(gfield::build_paths::data_dir()));
  fs::remove_all(kDir);
}

}  // namespace
}  // namespace gfield
