#pragma once
// The interactive gfield-view window: GLFW + Dear ImGui around a ViewSession. The picture fills
// the left of the window and the panel is docked on the right, so it never covers the picture.
// The panel switches the method (every method of the registry), a second method on the right
// half of the picture and the difference against a reference picture, and shows the current
// method's options; objects move without re-uploading the scene. The picture is rendered again
// only when something it depends on changed (camera, method, options, scene, size).

#include <filesystem>
#include <string>

#include "gfield/scene.hpp"
#include "runtime/view_session.hpp"

namespace gfield {

/// Keyboard and mouse controls, one per line (printed by --help and shown in the panel).
const char* viewer_shortcuts();

struct ViewerOptions {
  int method = 0;   ///< the session's method index shown first
  int width = 512;  ///< the picture's size in pixels (shrunk to fit a screen)
  int height = 512;
  /// The command that shows this scene (e.g. "gfield-view SCENE --assets DIR"), printed with
  /// each screenshot as the start of the command that renders it headless.
  std::string command;
};

/// Opens a window on `scene` showing `session` and runs until it is closed. Returns the process
/// exit code (0, or kExitNoOpenGL / 2 with a message on stderr).
int run_viewer(ViewSession& session, const Scene& scene, const std::filesystem::path& shader_dir,
               const ViewerOptions& options);

}  // namespace gfield
