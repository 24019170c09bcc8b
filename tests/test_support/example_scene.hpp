#pragma once
// An example scene of data/scenes, as JSON text, with its mesh objects' assets built into
// `folder` by `gfield batch` with the defaults of `gfield build` (as scripts/demo.sh builds
// them); batch rebuilds an asset whose build id no longer matches its mesh and options, so a
// folder left by an older build is never used. Tests that run side by side use folders of their
// own.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support/build_paths.hpp"

namespace gfield::test {

inline std::string example_scene(const std::string& name, const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  const fs::path source = fs::path(gfield::build_paths::data_dir()) / "scenes" / (name + ".json");
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(source));
  for (auto& object : scene["objects"]) {
    if (object["shape"] != "mesh")
      continue;
    const fs::path mesh =
        fs::weakly_canonical(source.parent_path() / object["file"].get<std::string>());
    const fs::path asset = folder / mesh.stem();
    const std::string command = std::string("\"") + gfield::build_paths::cli() + "\" batch \"" +
                                mesh.string() + "\" -o \"" + folder.string() +
                                "\" --verify-rays 0 > /dev/null 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    object["file"] = mesh.string();
    object["gimage"] = asset.string() + ".gimage.exr";
    object["gfield"] = asset.string() + ".gfield.exr";
  }
  return scene.dump();
}

}  // namespace gfield::test
