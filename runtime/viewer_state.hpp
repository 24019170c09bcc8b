#pragma once
// What the interactive viewer (runtime/viewer.cpp) keeps between frames: the session it shows,
// the camera, the selection, a mouse drag in progress and what the panel asked for. Input
// callbacks (runtime/viewer_input.cpp) and the panel (runtime/viewer_panel.cpp) change it; the
// frame loop draws from it.

#include <string>

#include "gfield/scene.hpp"
#include "runtime/view_session.hpp"

namespace gfield {

/// A method switch asked for (keys m and n, the panel's combos). A method's first use loads its
/// assets and shaders, which can take seconds, so the switch is made at the start of the frame
/// after one that showed "loading ..." in the panel.
struct MethodSwitch {
  bool pending = false;
  bool right_half = false;  ///< the right half's method instead of the one shown
  bool next = false;        ///< the next method that can draw the scene ("off" after the last)
  int to = -1;              ///< without `next`: this method (-1 with right_half: off)
  int frames_shown = 0;     ///< frames presented since it was asked for
};

struct ViewerState {
  ViewSession* session = nullptr;
  Camera camera;
  Camera initial_camera;
  int selected = -1;  ///< object index, -1: none
  bool show_panel = true;
  bool screenshot = false;  ///< save the next frame (key p)
  bool reload = false;      ///< rebuild the shaders now (key r)
  bool input = false;       ///< an input event arrived since the last frame
  MethodSwitch method_switch;

  // The cursor as of the last motion event and a mouse drag in progress (screen coordinates).
  bool dragging = false;
  int drag_button = -1;  ///< 0 left, 1 right
  bool drag_moves_object = false;
  bool drag_pans = false;
  double last_x = 0.0, last_y = 0.0;
  double press_x = 0.0, press_y = 0.0;

  // The picture's area as of the last frame: the left picture_width x picture_height screen
  // coordinates of the window, `scale` framebuffer pixels per screen coordinate.
  int picture_width = 1;
  int picture_height = 1;
  float scale = 1.0f;

  std::string shader_error;
  std::string message;  ///< the panel's last message (errors, "saved ...")
  char reference_path[512] = "";
  /// How this view is rendered again without a window (e.g. "gfield-view SCENE --assets DIR"):
  /// a screenshot prints it with the method, its options, the size and the camera.
  std::string command;
};

}  // namespace gfield
