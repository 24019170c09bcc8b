#pragma once
// Running another of gfield's programs: gfield-view runs `gfield` (assets, builds, thickness
// maps), `gfield export-web` runs gfield-view. Each looks for the other in the same places and
// waits for it the same way.

#include <string>
#include <vector>

namespace gfield {

/// The program `name` to run: $`env_var` when set and not empty, else `name` beside the running
/// executable (an install), else `build_tree` when that file exists, else `name` (the PATH).
std::string sibling_executable(const char* env_var, const std::string& name,
                               const std::string& build_tree);

/// Runs `argv` (argv[0] looked up on the PATH when it has no '/'), its stderr ours and its stdout
/// ours too, or our stderr with `stdout_to_stderr`, and waits for it (through EINTR): its wait
/// status in `status`; false when it could not be started.
bool run_child(std::vector<std::string> argv, bool stdout_to_stderr, int& status);

/// A child's exit code from its wait status: 0-255 when it exited, 128 + the signal that killed it.
int child_exit_code(int status);

}  // namespace gfield
