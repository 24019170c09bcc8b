#pragma once
// The subcommands of the `gfield` CLI, one file each. Each adds its subcommand to `app`; the
// callback runs the command and throws CommandError on failure (main prints it, exit code 2).

#include <stdexcept>
#include <string>

namespace CLI {
class App;
}

namespace gfield {

/// A failure the user caused (bad input) or that stops a command: one line, exit code 2.
struct CommandError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void add_info_command(CLI::App& app);
void add_field_command(CLI::App& app);
void add_build_command(CLI::App& app);
void add_batch_command(CLI::App& app);
void add_verify_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_image_command(CLI::App& app);
void add_thickness_command(CLI::App& app);

}  // namespace gfield
