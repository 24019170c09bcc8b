// gfield build MESH -o DIR/NAME: geometry image + geometry field + report of one mesh.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>

#include "gfield/printable.hpp"
#include "preprocess/cli/asset_options.hpp"
#include "preprocess/cli/commands.hpp"
#include "preprocess/thread_limit.hpp"

namespace gfield {

void add_build_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "build",
      "Build a whole asset from a mesh: NAME.gimage.exr + NAME.gimage.obj (geometry image and\n"
      "its parameterised mesh), NAME.gfield.exr (geometry field) and NAME.report.json\n"
      "(topology, route, times, sizes, accuracy against exact casts), all carrying one build id.\n"
      "The files are written into a staging folder and replace the old asset together, or not\n"
      "at all; build folders of killed builds in DIR are removed first.");
  auto mesh = std::make_shared<std::string>();
  auto name = std::make_shared<std::string>();
  auto threads = std::make_shared<int>(0);
  auto part = std::make_shared<std::string>();
  auto args = std::make_shared<AssetArguments>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("MESH", *mesh, mesh_file_help())->required();
  cmd->add_option("--mesh", *part,
                  "glTF: the mesh NAME (or #INDEX) to build (default: every primitive of the "
                  "file's scene, placed by its nodes, as one mesh)");
  cmd->add_option("-o,--output", *name, "output path without extension (DIR/NAME)")->required();
  cmd->add_option("--threads", *threads, "threads (0: all cores)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  add_asset_options(cmd, args);
  cmd->add_flag("--json", *json,
                "print the report (NAME.report.json, its stage_seconds included) instead of the "
                "summary");
  cmd->callback([mesh, name, threads, part, args, json] {
    const ThreadLimit limit(*threads);
    AssetOptions options = asset_options(*args);
    options.part = *part;
    AssetReport report;
    size_t stale = 0;
    std::string error;
    const bool built = build_asset_at(*mesh, *name, options, report, stale, error);
    if (stale > 0) {
      const std::filesystem::path dir = std::filesystem::path(*name).parent_path();
      std::printf("removed %zu build folders of killed builds in %s\n", stale,
                  dir.empty() ? "." : dir.c_str());
    }
    if (!built) {
      throw CommandError(error);
    }
    if (*json) {
      std::printf("%s\n", asset_report_to_json(report).dump(2).c_str());
      return;
    }
    print_warnings(report.warnings);
    std::printf(
        "%s: %s\n%s\nwrote %s.{gimage.exr,gimage.obj,gfield.exr,report.json} in %.2f s "
        "(build %s)\n",
        printable(*mesh).c_str(), asset_summary(report).c_str(), stage_summary(report).c_str(),
        printable(*name).c_str(), report.seconds, report.build_id.c_str());
  });
}

}  // namespace gfield
