#pragma once
// The interactive gfield-view window: GLFW + Dear ImGui around a ViewSession. The picture fills
// the left of the window and the panel is docked on the right, so it never covers the picture.
// The panel switches the method (every method of the registry), a second method on the right
// half of the picture and the difference against a reference picture, and shows the current
// method's options; objects move without re-uploading the scene.

#include <filesystem>

#include "gfield/scene.hpp"
#include "runtime/view_session.hpp"

namespace gfield {

/// Keyboard and mouse controls, one per line (printed by --help and shown in the panel).
const char* viewer_shortcuts();

/// Opens a window on `scene` showing `session`'s method `method` (an index of the session) and
/// runs until it is closed; the picture is width x height (shrunk to fit a screen). Returns the
/// process exit code (0, or kExitNoOpenGL / 2 with a message on stderr).
int run_viewer(ViewSession& session, const Scene& scene, const std::filesystem::path& shader_dir,
               int method, int width, int height);

}  // namespace gfield
