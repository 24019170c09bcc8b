#pragma once
// The interactive viewer's ImGui panel, docked right of the picture: renderer and picture
// figures, the method and the right half's method with their options, the selected object's
// transform and material, the difference against a reference picture, messages and shortcuts.

#include "runtime/gl_context.hpp"
#include "runtime/method.hpp"
#include "runtime/viewer_state.hpp"

namespace gfield {

/// Figures of the picture shown: the frame that rendered it and how fast the window redraws.
struct PictureFigures {
  FrameStats stats;         ///< the method's counts and parts of the picture shown
  double render_ms = 0.0;   ///< the last rendered picture (both halves, difference included)
  double window_ms = 16.0;  ///< the window's frames (presenting an unchanged picture is cheap)
};

/// Width of the panel in screen coordinates.
inline constexpr int kPanelWidth = 380;

/// Builds the panel (between ImGui::NewFrame and ImGui::Render) over the right kPanelWidth of a
/// window of window_width x window_height screen coordinates.
void viewer_panel(ViewerState& s, const GlContext& context, const PictureFigures& figures,
                  int window_width, int window_height);

}  // namespace gfield
