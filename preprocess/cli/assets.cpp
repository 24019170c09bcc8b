// gfield assets SCENE [--assets DIR]: builds the assets of every mesh of a scene (JSON or glTF)
// that are missing or out of date, with `gfield batch`'s rule (build ids); gfield-view runs it
// for glTF scenes (docs/scenes.md, "glTF scenes").

#include <CLI/CLI.hpp>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "geometry/scene_file.hpp"
#include "gfield/printable.hpp"
#include "preprocess/asset_files.hpp"
#include "preprocess/asset_staging.hpp"
#include "preprocess/cli/asset_options.hpp"
#include "preprocess/cli/commands.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

struct AssetsArguments {
  std::string scene;
  std::string dir;
  AssetArguments asset;
};

/// Builds (or finds up to date) the asset of `mesh` as DIR/NAME; one line on stdout.
void build_mesh_asset(const MeshAsset& mesh, const std::string& dir, const AssetArguments& args) {
  const std::string name = (fs::path(dir) / mesh.asset).string();
  AssetOptions options = asset_options(args);
  options.part = mesh.part;
  BuildInputs inputs;
  std::string error, why;
  if (!asset_build_inputs(mesh.file, options, inputs, error)) {
    throw CommandError(error);
  }
  if (asset_is_build(asset_files(name), inputs.build_id, why)) {
    std::printf("%s: up to date (build %s)\n", printable(name).c_str(), inputs.build_id.c_str());
    return;
  }
  AssetReport report;
  if (!build_asset(mesh.file, name, options, inputs, report, error)) {
    throw CommandError(error);
  }
  print_warnings(report.warnings);
  std::printf("%s: built (%s)\n", printable(name).c_str(), asset_summary(report).c_str());
  std::fflush(stdout);
}

void run_assets(const AssetsArguments& args) {
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  if (!load_scene_file(args.scene, scene, warnings, error,
                       outside_paths(args.asset.allow_outside_paths))) {
    throw CommandError(error);
  }
  print_warnings(warnings);
  std::vector<std::string> dirs;
  for (const MeshAsset& mesh : scene.meshes) {
    const std::string dir =
        args.dir.empty() ? fs::path(mesh.file).parent_path().string() : args.dir;
    dirs.push_back(dir.empty() ? "." : dir);
    std::error_code ec;
    fs::create_directories(dirs.back(), ec);
  }
  std::vector<std::string> folders = dirs;
  std::sort(folders.begin(), folders.end());
  folders.erase(std::unique(folders.begin(), folders.end()), folders.end());
  for (const std::string& dir : folders)
    remove_stale_staging(dir);
  // The meshes side by side: one build's serial stages (repair, parameterisation, writes) run
  // while another's parallel ones do. A failure stops the others' start and is reported.
  tbb::parallel_for(size_t(0), scene.meshes.size(), size_t(1),
                    [&](size_t m) { build_mesh_asset(scene.meshes[m], dirs[m], args.asset); });
}

}  // namespace

void add_assets_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "assets",
      "Build the assets (geometry image, field, report) of every mesh of a scene (JSON or\n"
      "glTF) that are missing or out of date (the build id rule of gfield batch): a glTF mesh\n"
      "as STEM.INDEX-NAME, another mesh as its file's stem, beside its file or in --assets DIR.");
  auto args = std::make_shared<AssetsArguments>();
  cmd->add_option("SCENE", args->scene, "scene file (.json, .gltf, .glb)")->required();
  cmd->add_option("--assets", args->dir, "folder of the assets (default: beside each mesh file)");
  add_asset_options(cmd, std::shared_ptr<AssetArguments>(args, &args->asset));
  cmd->callback([args] { run_assets(*args); });
}

}  // namespace gfield
