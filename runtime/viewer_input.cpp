#include "runtime/viewer_input.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "gfield/gpu_contract.hpp"
#include "runtime/viewer.hpp"
#include "runtime/viewer_state.hpp"

namespace gfield {

const char* viewer_shortcuts() {
  return "  left drag          orbit the camera around its target\n"
         "  right drag         pan (shift + left drag too)\n"
         "  wheel              zoom (move towards the target)\n"
         "  left click         select the object under the cursor (click empty space: none)\n"
         "  ctrl + left drag   move the selected object in the view plane\n"
         "  page up / down     move the selected object towards / away from the camera\n"
         "  1 / 2 / 3          lookup mode nearest / linear / refined (methods with --mode)\n"
         "  + / -              recursion depth up / down (methods with --depth)\n"
         "  f                  self-reflection on / off (methods with --no-self-reflection)\n"
         "  m                  next method\n"
         "  n                  next method on the right half (after the last: off)\n"
         "  r                  reload the shaders now (they also reload when their files change)\n"
         "  p                  screenshot: gfield-view-N.png in the current folder (N after the\n"
         "                     last one there) and, on stdout, the command that renders it "
         "headless\n"
         "  c                  camera back to the scene's\n"
         "  h                  hide / show the panel\n"
         "  esc                quit\n";
}

namespace {

ViewerState& state(GLFWwindow* window) {
  return *static_cast<ViewerState*>(glfwGetWindowUserPointer(window));
}

/// The current method's option called `name`, if it has one.
std::optional<MethodOption> option_named(ViewSession& session, const std::string& name) {
  for (const MethodOption& o : session.method(session.current()).options())
    if (o.name == name)
      return o;
  return std::nullopt;
}

/// The object whose world bounds the ray enters first (a cheap pick), or -1.
int pick(const GpuScene& scene, glm::vec3 origin, glm::vec3 direction) {
  int best = -1;
  float best_t = gpu::GF_FAR;
  for (int k = 0; k < int(scene.scene().objects.size()); ++k) {
    glm::vec3 lo, hi;
    scene.object_world_bounds(k, lo, hi);
    float t0 = 0.0f, t1 = gpu::GF_FAR;
    bool hit = true;
    for (int a = 0; a < 3 && hit; ++a) {
      const float inv = 1.0f / direction[a];
      float ta = (lo[a] - origin[a]) * inv, tb = (hi[a] - origin[a]) * inv;
      if (ta > tb)
        std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      hit = t0 <= t1;
    }
    if (hit && t0 < best_t) {
      best_t = t0;
      best = k;
    }
  }
  return best;
}

void orbit(Camera& camera, float dx, float dy) {
  const glm::vec3 offset = camera.position - camera.target;
  const float radius = glm::length(offset);
  float yaw = std::atan2(offset.x, offset.z);
  float pitch = std::asin(std::clamp(offset.y / radius, -1.0f, 1.0f));
  yaw -= dx * 0.005f;
  pitch = std::clamp(pitch + dy * 0.005f, -1.5f, 1.5f);
  camera.position =
      camera.target + radius * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                         std::cos(pitch) * std::cos(yaw));
  camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
}

/// Moves by a screen offset (pixels) in the plane through `anchor` facing the camera.
glm::vec3 screen_offset(const Camera& camera, int height, glm::vec3 anchor, float dx, float dy) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 up = glm::cross(right, forward);
  const float depth = glm::dot(anchor - camera.position, forward);
  const float per_pixel =
      2.0f * depth * std::tan(glm::radians(camera.fov_degrees) * 0.5f) / float(height);
  return (dx * right - dy * up) * per_pixel;
}

/// Shows the next method after the current one that can draw the scene; with `right_half`, on
/// the right half, where "off" comes after the last method.
void next_method(ViewerState& s, bool right_half) {
  ViewSession& session = *s.session;
  const int count = session.method_count() + (right_half ? 1 : 0);
  const int from = right_half ? session.compare() + 1 : session.current();
  for (int step = 1; step < count + 1; ++step) {
    const int k = (from + step) % count;
    const int method = right_half ? k - 1 : k;
    std::string error;
    if (right_half ? session.select_compare(method, error) : session.select(method, error))
      return;
    s.message = "skipped " + session.method(method).info().name + ": " + error;
  }
}

/// The method a switch leads to first (the next one may fail to load and be skipped).
int switch_target(const ViewerState& s, const MethodSwitch& w) {
  const ViewSession& session = *s.session;
  if (!w.next)
    return w.to;
  if (w.right_half)
    return session.compare() + 1 < session.method_count() ? session.compare() + 1 : -1;
  return (session.current() + 1) % session.method_count();
}

/// Keys 1-3, +/- and f set the current method's options "mode", "depth", "no-self-reflection";
/// m and n switch methods.
void method_key(ViewerState& s, int key) {
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_3) {
    if (auto o = option_named(*s.session, "mode"))
      o->set_choice(key - GLFW_KEY_1);
  } else if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD || key == GLFW_KEY_MINUS ||
             key == GLFW_KEY_KP_SUBTRACT) {
    const int step = key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD ? 1 : -1;
    if (auto o = option_named(*s.session, "depth"))
      *o->int_value = std::clamp(*o->int_value + step, int(o->min), int(o->max));
  } else if (key == GLFW_KEY_F) {
    if (auto o = option_named(*s.session, "no-self-reflection"))
      *o->flag_value = !*o->flag_value;
  } else if (key == GLFW_KEY_M || key == GLFW_KEY_N) {
    request_method_switch(s, key == GLFW_KEY_N, true);
  }
}

void key_callback(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  ViewerState& s = state(window);
  s.input = true;
  if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard)
    return;
  Scene& scene = s.session->scene().scene();
  switch (key) {
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(window, GLFW_TRUE);
      break;
    case GLFW_KEY_R:
      s.reload = true;
      break;
    case GLFW_KEY_P:
      s.screenshot = true;
      break;
    case GLFW_KEY_C:
      s.camera = s.initial_camera;
      break;
    case GLFW_KEY_H:
      s.show_panel = !s.show_panel;
      break;
    case GLFW_KEY_PAGE_UP:
    case GLFW_KEY_PAGE_DOWN:
      if (s.selected >= 0) {
        glm::vec3& t = scene.objects[size_t(s.selected)].transform.translate;
        const glm::vec3 towards = glm::normalize(s.camera.position - t);
        t += (key == GLFW_KEY_PAGE_UP ? 0.05f : -0.05f) * s.session->scene().extent() * towards;
        s.session->scene_changed();
      }
      break;
    default:
      method_key(s, key);
      break;
  }
}

/// A drag moved by (dx, dy) screen coordinates: orbit, pan or move the selected object.
void drag(ViewerState& s, float dx, float dy) {
  if (s.drag_moves_object) {
    glm::vec3& t = s.session->scene().scene().objects[size_t(s.selected)].transform.translate;
    t += screen_offset(s.camera, s.picture_height, t, dx, dy);
    s.session->scene_changed();
  } else if (s.drag_pans) {
    const glm::vec3 offset = screen_offset(s.camera, s.picture_height, s.camera.target, -dx, -dy);
    s.camera.position += offset;
    s.camera.target += offset;
  } else {
    orbit(s.camera, dx, dy);
  }
}

bool over_picture(const ViewerState& s, double x, double y) {
  return x >= 0.0 && y >= 0.0 && x < s.picture_width && y < s.picture_height &&
         !ImGui::GetIO().WantCaptureMouse;
}

void mouse_button_callback(GLFWwindow* window, int button, int action, int mods) {
  ViewerState& s = state(window);
  s.input = true;
  if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT)
    return;
  // Where the last motion event put the cursor (glfwGetCursorPos would say where it is now,
  // after events not yet handled).
  const double x = s.last_x, y = s.last_y;
  const bool left = button == GLFW_MOUSE_BUTTON_LEFT;
  if (action == GLFW_PRESS && !s.dragging && over_picture(s, x, y)) {
    s.dragging = true;
    s.drag_button = left ? 0 : 1;
    s.press_x = x;
    s.press_y = y;
    s.drag_moves_object = left && (mods & GLFW_MOD_CONTROL) != 0 && s.selected >= 0;
    s.drag_pans = !left || (mods & GLFW_MOD_SHIFT) != 0;
  } else if (action == GLFW_RELEASE && s.dragging && s.drag_button == (left ? 0 : 1)) {
    // A click without movement selects.
    if (left && std::abs(x - s.press_x) + std::abs(y - s.press_y) < 3.0) {
      const CameraRay ray =
          camera_ray(s.camera, int(float(s.picture_width) * s.scale),
                     int(float(s.picture_height) * s.scale), {x * s.scale, y * s.scale});
      s.selected = pick(s.session->scene(), glm::vec3(ray.origin), glm::vec3(ray.direction));
    }
    s.dragging = false;
  }
}

void cursor_callback(GLFWwindow* window, double x, double y) {
  ViewerState& s = state(window);
  s.input = true;
  if (s.dragging)
    drag(s, float(x - s.last_x), float(y - s.last_y));
  s.last_x = x;
  s.last_y = y;
}

void scroll_callback(GLFWwindow* window, double /*dx*/, double dy) {
  ViewerState& s = state(window);
  s.input = true;
  if (!over_picture(s, s.last_x, s.last_y))
    return;
  const glm::vec3 offset = s.camera.position - s.camera.target;
  s.camera.position = s.camera.target + offset * std::pow(0.9f, float(dy));
}

void wake(GLFWwindow* window) {
  state(window).input = true;
}

}  // namespace

void request_method_switch(ViewerState& s, bool right_half, bool next, int to) {
  s.method_switch = MethodSwitch{true, right_half, next, to, 0};
  const int target = switch_target(s, s.method_switch);
  if (target >= 0 && !s.session->loaded(target))
    s.message = "loading " + s.session->method(target).info().title + " ...";
  else
    switch_method_if_due(s);
}

void switch_method_if_due(ViewerState& s) {
  MethodSwitch& w = s.method_switch;
  const int target = switch_target(s, w);
  const bool loads = target >= 0 && !s.session->loaded(target);
  if (!w.pending || (loads && w.frames_shown == 0))
    return;
  w.pending = false;
  s.message.clear();
  ViewSession& session = *s.session;
  if (w.next)
    next_method(s, w.right_half);
  else if (!(w.right_half ? session.select_compare(w.to, s.message)
                          : session.select(w.to, s.message)))
    s.message = session.method(w.to).info().name + ": " + s.message;
}

void install_input_callbacks(GLFWwindow* window) {
  glfwSetKeyCallback(window, key_callback);
  glfwSetMouseButtonCallback(window, mouse_button_callback);
  glfwSetCursorPosCallback(window, cursor_callback);
  glfwSetScrollCallback(window, scroll_callback);
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int) { wake(w); });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { wake(w); });
  glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { wake(w); });
  glfwSetWindowRefreshCallback(window, wake);
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { wake(w); });
}

}  // namespace gfield
