#pragma once
// The subcommands of the `gfield` CLI, one file each. Each adds its subcommand to `app`; the
// callback runs the command and throws CommandError on failure (main prints it, exit code 2).

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/mesh_formats.hpp"
#include "gfield/printable.hpp"

namespace CLI {
class App;
}

namespace gfield {

/// A failure the user caused (bad input) or that stops a command: one line, exit code 2.
struct CommandError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A command that ran another program, which failed and said why: exit with its status.
struct CommandExit {
  int status = 2;
};

/// Prints each warning as "gfield: warning: WARNING" on stderr (the command goes on).
inline void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) {
    std::fprintf(stderr, "gfield: warning: %s\n", printable(w).c_str());
  }
}

/// The help of a MESH argument: "mesh file (.obj, .ply, ...)", every format
/// (geometry/mesh_formats.hpp).
inline std::string mesh_file_help() {
  return "mesh file (" + mesh_extension_list() + ")";
}

void add_info_command(CLI::App& app);
void add_field_command(CLI::App& app);
void add_build_command(CLI::App& app);
void add_batch_command(CLI::App& app);
void add_verify_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_image_command(CLI::App& app);
void add_thickness_command(CLI::App& app);
void add_assets_command(CLI::App& app);
void add_export_gltf_command(CLI::App& app);
void add_export_web_command(CLI::App& app);

}  // namespace gfield
