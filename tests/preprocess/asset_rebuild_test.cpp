// One process building an asset again and again (the Python module's gfield.build in one
// session; a later process with the pid of an earlier one finds the same folders): a build
// folder's name must not be that of the published one (docs/formats.md, "Publishing").

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "preprocess/asset_build.hpp"
#include "preprocess/asset_files.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = test::process_folder("asset_rebuild");

AssetOptions small_options(int samples) {
  AssetOptions options;
  options.image.size = 64;
  options.image.measure = false;
  options.samples_per_side = samples;
  options.verify_rays = 0;
  return options;
}

/// Builds spot into kDir/spot with N = `samples`; returns the build id.
std::string build_spot(int samples) {
  AssetReport report;
  size_t stale = 0;
  std::string error;
  const std::string mesh = std::string(gfield::build_paths::mesh_dir()) + "/spot.obj";
  EXPECT_TRUE(
      build_asset_at(mesh, (kDir / "spot").string(), small_options(samples), report, stale, error))
      << error;
  return report.build_id;
}

TEST(AssetRebuild, OneProcessBuildsTheSameAssetAgainAndAgain) {
  fs::remove_all(kDir);
  for (int samples : {4, 5, 4, 6}) {
    const std::string id = build_spot(samples);
    std::string why;
    EXPECT_TRUE(asset_is_build(asset_files((kDir / "spot").string()), id, why)) << why;
  }
  fs::remove_all(kDir);
}

}  // namespace
}  // namespace gfield
