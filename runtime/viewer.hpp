#pragma once
// The interactive gfield-view window: GLFW + Dear ImGui around the Renderer.

#include <filesystem>
#include <string>

#include "gfield/scene.hpp"
#include "runtime/renderer.hpp"

namespace gfield {

/// Keyboard and mouse controls, one per line (printed by --help and shown in the panel).
const char* viewer_shortcuts();

/// Opens a window on `scene` and runs until it is closed. Returns the process exit code (0, or
/// kExitNoOpenGL / 2 with a message on stderr).
int run_viewer(const Scene& scene, const std::filesystem::path& shader_dir,
               const RenderSettings& settings, int width, int height);

}  // namespace gfield
