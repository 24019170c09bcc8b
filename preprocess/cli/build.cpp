// gfield build MESH -o DIR/NAME: geometry image + geometry field + report of one mesh.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>

#include "gfield/printable.hpp"
#include "preprocess/cli/asset_options.hpp"
#include "preprocess/cli/commands.hpp"

namespace gfield {

void add_build_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "build",
      "Build a whole asset from a mesh: NAME.gimage.exr + NAME.gimage.obj (geometry image and\n"
      "its parameterised mesh), NAME.gfield.exr (geometry field) and NAME.report.json\n"
      "(topology, route, times, sizes, accuracy against exact casts).");
  auto mesh = std::make_shared<std::string>();
  auto name = std::make_shared<std::string>();
  auto args = std::make_shared<AssetArguments>();
  cmd->add_option("MESH", *mesh, "mesh file (.obj, .ply, .off, .stl)")->required();
  cmd->add_option("-o,--output", *name, "output path without extension (DIR/NAME)")->required();
  add_asset_options(cmd, args);
  cmd->callback([mesh, name, args] {
    const std::filesystem::path dir = std::filesystem::path(*name).parent_path();
    std::error_code ec;
    if (!dir.empty()) {
      std::filesystem::create_directories(dir, ec);
    }
    nlohmann::json report;
    std::string error;
    if (!build_asset(*mesh, *name, asset_options(*args), report, error)) {
      throw CommandError(error);
    }
    std::printf("%s: %s\nwrote %s.{gimage.exr,gimage.obj,gfield.exr,report.json} in %.2f s\n",
                printable(*mesh).c_str(), asset_summary(report).c_str(), printable(*name).c_str(),
                report["seconds"].get<double>());
  });
}

}  // namespace gfield
