#pragma once
// --allow-outside-paths, of every command that reads glTF files, scenes or meshes that name other
// files (docs/scenes.md, "Confined paths").

#include <CLI/CLI.hpp>

#include "gfield/confined_path.hpp"

namespace gfield {

/// Adds --allow-outside-paths to `cmd`, bound to `allow`.
inline void add_outside_paths_option(CLI::App* cmd, bool& allow) {
  cmd->add_flag("--allow-outside-paths", allow,
                "read the files that a glTF file or a mesh names outside its folder, and that a "
                "scene names\noutside its root (docs/scenes.md, \"Confined paths\")");
}

/// The OutsidePaths of the flag's value.
inline OutsidePaths outside_paths(bool allow) {
  return allow ? OutsidePaths::kAllowed : OutsidePaths::kRefused;
}

}  // namespace gfield
