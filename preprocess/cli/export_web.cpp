// gfield export-web SCENE -o DIR: the web player and the scene as gfield-view draws it with
// geometry fields (docs/web.md). The export reads back the runtime's GPU scene, so gfield-view
// writes it (gfield-view SCENE --export-web DIR): gfield links no OpenGL. gfield-view is looked
// for as $GFIELD_VIEW, beside this executable, in the build tree, then on the PATH.

#include <CLI/CLI.hpp>

#include <sys/wait.h>

#include <memory>
#include <string>
#include <vector>

#include "gfield/child_program.hpp"
#include "preprocess/cli/commands.hpp"

namespace gfield {

namespace {

/// export-web's arguments.
struct ExportWebArguments {
  std::string scene;
  std::string output;
  std::string assets;
  std::string size;
  bool rebuild_stale = false;
  bool allow_outside = false;
};

}  // namespace

void add_export_web_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export-web",
      "Write DIR: the web player (index.html) and the scene as gfield-view draws it with\n"
      "geometry fields, in browser-ready files, for any static web server (docs/web.md). Runs\n"
      "gfield-view SCENE --export-web DIR: $GFIELD_VIEW, else the gfield-view beside gfield,\n"
      "else the build tree's, else the PATH's.");
  auto a = std::make_shared<ExportWebArguments>();
  cmd->add_option("SCENE", a->scene, "scene file (.json, .gltf, .glb)")->required();
  cmd->add_option("-o,--output", a->output, "the folder to write (new, or an earlier export)")
      ->required();
  cmd->add_option("--assets", a->assets,
                  "folder of prebuilt assets (NAME.gimage.exr/.gfield.exr for mesh NAME.obj)");
  cmd->add_option("--size", a->size, "the player's picture size WxH (default: the scene's)");
  cmd->add_flag("--rebuild-stale", a->rebuild_stale,
                "rebuild an asset built from another mesh or an older version of its mesh");
  cmd->add_flag("--allow-outside-paths", a->allow_outside,
                "read the files a scene or glTF file names outside its folder");
  cmd->callback([a] {
    std::vector<std::string> argv = {
        sibling_executable("GFIELD_VIEW", "gfield-view", GFIELD_BUILD_TREE_VIEW), a->scene,
        "--export-web", a->output};
    if (!a->assets.empty())
      argv.insert(argv.end(), {"--assets", a->assets});
    if (!a->size.empty())
      argv.insert(argv.end(), {"--size", a->size});
    if (a->rebuild_stale)
      argv.push_back("--rebuild-stale");
    if (a->allow_outside)
      argv.push_back("--allow-outside-paths");
    int status = 0;
    if (!run_child(argv, false, status))
      throw CommandError(argv[0] +
                         ": cannot be run (export-web needs gfield-view: install it, "
                         "or name it in GFIELD_VIEW)");
    if (WIFSIGNALED(status))
      throw CommandError(argv[0] + ": killed by signal " + std::to_string(WTERMSIG(status)) +
                         " (nothing was exported)");
    if (WEXITSTATUS(status) != 0)
      throw CommandExit{WEXITSTATUS(status)};  // gfield-view has said what went wrong
  });
}

}  // namespace gfield
