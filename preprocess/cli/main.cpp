// gfield: the preprocessing command line (mesh -> geometry image -> geometry field, verify,
// reference rendering). One subcommand per file in this folder.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "gfield/printable.hpp"
#include "preprocess/cli/commands.hpp"
#include "preprocess/worker_threads.hpp"

int main(int argc, char** argv) {
  const gfield::WorkerThreads workers;  // joined before the process exits
  CLI::App app{
      "gfield: geometry images and geometry fields for real-time reflection and refraction.\n"
      "Exit codes: 0 success, 2 bad input or failed command, 1 internal error.",
      "gfield"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "gfield 0.1.0");

  gfield::add_info_command(app);
  gfield::add_field_command(app);
  gfield::add_build_command(app);
  gfield::add_batch_command(app);
  gfield::add_verify_command(app);
  gfield::add_render_command(app);
  gfield::add_compare_command(app);
  gfield::add_image_command(app);
  gfield::add_thickness_command(app);
  gfield::add_assets_command(app);
  gfield::add_export_gltf_command(app);
  gfield::add_export_web_command(app);

  if (argc > 1 && argv[1][0] != '-') {  // a word that names no command: say so, not "required"
    const std::vector<CLI::App*> commands = app.get_subcommands([](CLI::App*) { return true; });
    std::string names;
    bool known = false;
    for (const CLI::App* command : commands) {
      names += (names.empty() ? "" : ", ") + command->get_name();
      known = known || command->get_name() == argv[1];
    }
    if (!known) {
      std::fprintf(stderr, "gfield: %s: no such command (the commands: %s; see gfield --help)\n",
                   gfield::printable(argv[1]).c_str(), names.c_str());
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "gfield: %s (see gfield --help)\n", gfield::printable(e.what()).c_str());
    return 2;
  } catch (const gfield::CommandExit& e) {
    return e.status;
  } catch (const gfield::CommandError& e) {
    std::fprintf(stderr, "gfield: error: %s\n", gfield::printable(e.what()).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gfield: internal error: %s\n", gfield::printable(e.what()).c_str());
    return 1;
  }
  return 0;
}
