#pragma once
// Keyboard and mouse of the interactive viewer, event by event (GLFW callbacks): keys switch
// methods and options, a drag orbits, pans or moves the selected object, a click selects, the
// wheel zooms. Every event is applied when it arrives, so a click or a drag shorter than a slow
// frame is never lost, and marks ViewerState::input so that an idle viewer wakes up.

struct GLFWwindow;

namespace gfield {

struct ViewerState;

/// Installs the viewer's callbacks on `window`, whose user pointer is the ViewerState. Call
/// before ImGui_ImplGlfw_InitForOpenGL(window, true): ImGui's callbacks then call these first.
void install_input_callbacks(GLFWwindow* window);

/// Asks for a method switch (ViewerState::method_switch): to method `to` (-1 with `right_half`:
/// the right half off), or with `next` to the next one that can draw the scene. A method already
/// loaded is switched to at once; otherwise the panel says "loading ..." first.
void request_method_switch(ViewerState& s, bool right_half, bool next, int to = -1);
/// Makes the switch asked for once a frame has shown that it is coming.
void switch_method_if_due(ViewerState& s);

}  // namespace gfield
