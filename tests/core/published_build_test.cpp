// The build an asset's files name now (published_build.hpp): the target of NAME.builds/current,
// nothing for plain files, and the asset's name taken from its image's or field's file name.

#include "gfield/published_build.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_support/test_files.hpp"

namespace gfield {
namespace {
namespace fs = std::filesystem;

TEST(PublishedBuild, IsTheFolderCurrentNamesAndNothingForPlainFiles) {
  const fs::path dir = test::process_folder("published_build");
  fs::remove_all(dir);
  fs::create_directories(dir / "spot.builds" / "p-7-0");
  const std::string spot = (dir / "spot").string();
  EXPECT_EQ(published_build(spot), "");  // no link yet
  fs::create_directory_symlink("p-7-0", dir / "spot.builds" / "current");
  EXPECT_EQ(published_build(spot), "p-7-0");
  fs::remove(dir / "spot.builds" / "current");
  fs::create_directory_symlink("p-7-1", dir / "spot.builds" / "current");  // dangling: as named
  EXPECT_EQ(published_build(spot), "p-7-1");
  std::ofstream(dir / "torus.gimage.exr") << "plain";
  EXPECT_EQ(published_build((dir / "torus").string()), "");
  fs::remove_all(dir);
}

TEST(PublishedBuild, TheAssetsNameIsItsImagesOrFieldsFileNameWithoutSuffix) {
  EXPECT_EQ(asset_name_of("out/spot.gimage.exr"), "out/spot");
  EXPECT_EQ(asset_name_of("out/spot.gfield.exr"), "out/spot");
  EXPECT_EQ(asset_name_of("spot.gimage.obj"), "");
  EXPECT_EQ(asset_name_of(".gfield.exr"), "");
  EXPECT_EQ(asset_name_of(""), "");
}

}  // namespace
}  // namespace gfield
