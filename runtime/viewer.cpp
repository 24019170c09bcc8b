#include "runtime/viewer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "gfield/gpu_contract.hpp"
#include "gfield/optics.hpp"
#include "gfield/printable.hpp"
#include "gfield/stopwatch.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/method_panel.hpp"

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
         "  r                  reload the shaders now (they also reload when their files change)\n"
         "  p                  screenshot: gfield-view-N.png in the current folder\n"
         "  c                  camera back to the scene's\n"
         "  h                  hide / show the panel\n"
         "  esc                quit\n";
}

namespace {

constexpr int kPanelWidth = 380;  ///< screen coordinates, docked right of the picture

struct ViewerState {
  ViewSession* session = nullptr;
  Camera camera;
  Camera initial_camera;
  int selected = -1;
  bool show_panel = true;
  bool screenshot = false;
  bool reload = false;
  double last_x = 0.0, last_y = 0.0;
  double press_x = 0.0, press_y = 0.0;
  bool dragging = false;
  int drag_button = -1;
  bool drag_moves_object = false;
  std::string shader_error;
  std::string message;
  char reference_path[512] = "";
  int screenshots = 0;
};

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
  float best_t = 3.0e38f;
  for (int k = 0; k < int(scene.scene().objects.size()); ++k) {
    glm::vec3 lo, hi;
    scene.object_world_bounds(k, lo, hi);
    float t0 = 0.0f, t1 = 3.0e38f;
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

/// Keys 1-3, +/- and f set the current method's options "mode", "depth", "no-self-reflection".
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
  } else if (key == GLFW_KEY_M) {
    ViewSession& session = *s.session;
    for (int step = 1; step < session.method_count(); ++step)
      if (session.select((session.current() + step) % session.method_count(), s.message))
        break;
  }
}

void key_callback(GLFWwindow* window, int key, int scancode, int action, int mods) {
  ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
  if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard)
    return;
  auto* s = static_cast<ViewerState*>(glfwGetWindowUserPointer(window));
  Scene& scene = s->session->scene().scene();
  switch (key) {
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(window, GLFW_TRUE);
      break;
    case GLFW_KEY_R:
      s->reload = true;
      break;
    case GLFW_KEY_P:
      s->screenshot = true;
      break;
    case GLFW_KEY_C:
      s->camera = s->initial_camera;
      break;
    case GLFW_KEY_H:
      s->show_panel = !s->show_panel;
      break;
    case GLFW_KEY_PAGE_UP:
    case GLFW_KEY_PAGE_DOWN:
      if (s->selected >= 0) {
        glm::vec3& t = scene.objects[size_t(s->selected)].transform.translate;
        const glm::vec3 towards = glm::normalize(s->camera.position - t);
        t += (key == GLFW_KEY_PAGE_UP ? 0.05f : -0.05f) * s->session->scene().extent() * towards;
        s->session->scene_changed();
      }
      break;
    default:
      method_key(*s, key);
      break;
  }
}

/// A mouse drag in progress: orbit, pan or move the selected object.
void drag(ViewerState& s, float dx, float dy, int height, bool shift) {
  if (s.drag_moves_object) {
    glm::vec3& t = s.session->scene().scene().objects[size_t(s.selected)].transform.translate;
    t += screen_offset(s.camera, height, t, dx, dy);
    s.session->scene_changed();
  } else if (s.drag_button == 1 || shift) {
    const glm::vec3 offset = screen_offset(s.camera, height, s.camera.target, -dx, -dy);
    s.camera.position += offset;
    s.camera.target += offset;
  } else {
    orbit(s.camera, dx, dy);
  }
}

/// Mouse input over the picture (picture_width x height screen coordinates, `scale` framebuffer
/// pixels per screen coordinate).
void handle_mouse(GLFWwindow* window, ViewerState& s, int picture_width, int height, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  const float dx = float(x - s.last_x), dy = float(y - s.last_y);
  s.last_x = x;
  s.last_y = y;
  if (io.WantCaptureMouse)
    return;
  const bool left = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool right = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  const bool ctrl = glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                    glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
  const bool shift = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS;
  if ((left || right) && !s.dragging) {
    s.dragging = true;
    s.drag_button = left ? 0 : 1;
    s.press_x = x;
    s.press_y = y;
    s.drag_moves_object = left && ctrl && s.selected >= 0;
  } else if (s.dragging && (left || right)) {
    drag(s, dx, dy, height, shift);
  } else if (s.dragging) {
    // Released: a click without movement selects.
    if (s.drag_button == 0 && std::abs(x - s.press_x) + std::abs(y - s.press_y) < 3.0) {
      const CameraRay ray = camera_ray(s.camera, int(float(picture_width) * scale),
                                       int(float(height) * scale), {x * scale, y * scale});
      s.selected = pick(s.session->scene(), glm::vec3(ray.origin), glm::vec3(ray.direction));
    }
    s.dragging = false;
  }
  if (io.MouseWheel != 0.0f) {
    const glm::vec3 offset = s.camera.position - s.camera.target;
    s.camera.position = s.camera.target + offset * std::pow(0.9f, io.MouseWheel);
  }
}

/// Shaders: reloaded on request or when a file changed (checked twice a second).
void check_shaders(ViewerState& s, Stopwatch& since_check) {
  if (!s.reload && since_check.milliseconds() < 500.0)
    return;
  std::string error;
  const bool rebuilt = s.session->reload_shaders_if_changed(error);
  if (!error.empty()) {
    s.shader_error = error;
    std::fprintf(stderr, "gfield-view: %s\n", printable(error).c_str());
  } else if (rebuilt) {
    s.shader_error.clear();
    s.message = "shaders reloaded";
  }
  s.reload = false;
  since_check.restart();
}

void methods_section(ViewerState& s) {
  ViewSession& session = *s.session;
  std::vector<std::string> titles;
  for (int k = 0; k < session.method_count(); ++k)
    titles.push_back(session.method(k).info().title);
  const auto combo = [&](const char* label, int current, bool with_off) {
    int choice = current;
    const char* preview = current >= 0 ? titles[size_t(current)].c_str() : "(off)";
    if (ImGui::BeginCombo(label, preview)) {
      if (with_off && ImGui::Selectable("(off)", current < 0))
        choice = -1;
      for (int k = 0; k < int(titles.size()); ++k)
        if (ImGui::Selectable(titles[size_t(k)].c_str(), k == current))
          choice = k;
      ImGui::EndCombo();
    }
    return choice;
  };
  const int method = combo("method", session.current(), false);
  if (method != session.current() && !session.select(method, s.message))
    s.message = session.method(method).info().name + ": " + s.message;
  const int compare = combo("right half", session.compare(), true);
  if (compare != session.compare() && !session.select_compare(compare, s.message))
    s.message = session.method(compare).info().name + ": " + s.message;
  method_panel(session.method(session.current()));
  if (session.compare() >= 0 && session.compare() != session.current() &&
      ImGui::CollapsingHeader("right half's options"))
    method_panel(session.method(session.compare()));
}

void difference_section(ViewerState& s) {
  ViewSession& session = *s.session;
  ImGui::InputText("reference", s.reference_path, sizeof(s.reference_path));
  ImGui::SameLine();
  if (ImGui::Button("load")) {
    Image reference;
    std::string error;
    if (load_image(s.reference_path, reference, error)) {
      session.set_reference(std::move(reference));
      s.message = std::string("reference ") + s.reference_path;
    } else {
      s.message = error;
    }
  }
  ImGui::Checkbox("difference to reference", &session.difference);
  ImGui::SameLine();
  ImGui::SliderFloat("white at", &session.difference_scale, 0.01f, 1.0f, "%.2f");
  if (session.difference)
    ImGui::TextWrapped("%s", session.difference_message().c_str());
}

/// The selected object's transform and material; true when one changed.
bool object_editor(SceneObject& o) {
  bool changed = ImGui::DragFloat3("translate", &o.transform.translate.x, 0.01f);
  changed |= ImGui::DragFloat3("rotate", &o.transform.rotate_degrees.x, 0.5f);
  int type = int(o.material.type);
  const char* types[] = {"diffuse", "mirror", "dielectric"};
  if (ImGui::Combo("material", &type, types, shape_is_closed(o.shape.type) ? 3 : 2)) {
    o.material.type = MaterialType(type);
    changed = true;
  }
  if (o.material.type != MaterialType::kDielectric)
    return changed | ImGui::ColorEdit3(o.material.type == MaterialType::kMirror ? "tint" : "colour",
                                       &o.material.color.x);
  changed |= ImGui::SliderFloat("index", &o.material.ior, 1.0f, 2.5f);
  if (ImGui::BeginCombo("preset", o.material.ior_preset.c_str())) {
    for (const IorPreset& preset : ior_presets()) {
      const std::string label =
          std::string(preset.name) + " (" + std::to_string(preset.index).substr(0, 5) + ")";
      if (ImGui::Selectable(label.c_str())) {
        o.material.ior = preset.index;
        o.material.ior_preset = std::string(preset.name);
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed | ImGui::ColorEdit3("absorption", &o.material.absorption.x,
                                     ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
}

void objects_section(ViewerState& s) {
  Scene& scene = s.session->scene().scene();
  std::vector<std::string> names;
  for (size_t k = 0; k < scene.objects.size(); ++k)
    names.push_back(scene.objects[k].name.empty() ? "object " + std::to_string(k)
                                                  : scene.objects[k].name);
  if (ImGui::BeginCombo("object", s.selected >= 0 ? names[size_t(s.selected)].c_str() : "(none)")) {
    if (ImGui::Selectable("(none)", s.selected < 0))
      s.selected = -1;
    for (size_t k = 0; k < names.size(); ++k)
      if (ImGui::Selectable(names[k].c_str(), int(k) == s.selected))
        s.selected = int(k);
    ImGui::EndCombo();
  }
  if (s.selected >= 0 && object_editor(scene.objects[size_t(s.selected)]))
    s.session->scene_changed();
}

void panel(ViewerState& s, const GlContext& context, const FrameStats& stats, double frame_ms,
           int window_width, int window_height) {
  ImGui::SetNextWindowPos(ImVec2(float(window_width - kPanelWidth), 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(float(kPanelWidth), float(window_height)), ImGuiCond_Always);
  ImGui::Begin("gfield-view", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  ImGui::Text("%s", context.renderer().c_str());
  ImGui::Text("frame %.1f ms (%.1f FPS)", frame_ms, 1000.0 / std::max(frame_ms, 1e-3));
  for (const auto& [name, value] : stats.counts)
    ImGui::Text("%s %.0f", name.c_str(), value);
  ImGui::Text("texture memory %.1f MB", double(s.session->scene().assets().texture_bytes()) / 1e6);
  const GpuScene& scene = s.session->scene();
  ImGui::TextUnformatted(asset_memory_lines(scene.scene(), scene.assets()).c_str());
  ImGui::Separator();
  methods_section(s);
  ImGui::Separator();
  objects_section(s);
  ImGui::Separator();
  difference_section(s);
  ImGui::Separator();
  if (ImGui::Button("screenshot (p)"))
    s.screenshot = true;
  ImGui::SameLine();
  if (ImGui::Button("reload shaders (r)"))
    s.reload = true;
  if (!s.message.empty())
    ImGui::TextWrapped("%s", s.message.c_str());
  if (!s.shader_error.empty())
    ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", s.shader_error.c_str());
  if (ImGui::CollapsingHeader("shortcuts"))
    ImGui::TextUnformatted(viewer_shortcuts());
  ImGui::End();
}

void save_screenshot(ViewerState& s, const Framebuffer& frame) {
  const Image image = frame.read_image();
  const std::string name = "gfield-view-" + std::to_string(s.screenshots++) + ".png";
  std::string error;
  s.message = save_image(name, image, error) ? "saved " + name : error;
  s.screenshot = false;
}

/// Draws the session's frame into the left `picture_width` framebuffer pixels of the window.
void present(ViewSession& session, const ShaderProgram& program, const Framebuffer& frame) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, frame.width(), frame.height());
  glUseProgram(program.id());
  glBindTextureUnit(gpu::UNIT_FRAME, frame.color_texture());
  session.scene().draw_fullscreen();
}

/// One iteration of the window's loop; false when the window has no area.
bool viewer_frame(GLFWwindow* window, ViewerState& s, const GlContext& context,
                  const ShaderProgram& present_program, Framebuffer& frame, FrameStats& shown,
                  double& frame_ms, int frame_number) {
  int fb_width = 0, fb_height = 0, win_width = 0, win_height = 0;
  glfwGetFramebufferSize(window, &fb_width, &fb_height);
  glfwGetWindowSize(window, &win_width, &win_height);
  const float scale = float(fb_width) / float(std::max(win_width, 1));
  const int picture_width = std::max(1, win_width - (s.show_panel ? kPanelWidth : 0));
  if (fb_width <= 0 || fb_height <= 0)
    return false;
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  handle_mouse(window, s, picture_width, win_height, scale);
  const Stopwatch clock;
  frame.resize(int(float(picture_width) * scale), fb_height);
  // Counting reads buffers back: every 30 frames.
  FrameStats stats;
  s.session->draw(s.camera, frame, frame_number % 30 == 0 ? &stats : nullptr);
  if (frame_number % 30 == 0)
    shown = stats;
  present(*s.session, present_program, frame);
  if (s.screenshot)
    save_screenshot(s, frame);
  if (s.show_panel)
    panel(s, context, shown, frame_ms, win_width, win_height);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(window);
  glFinish();
  frame_ms = 0.9 * frame_ms + 0.1 * clock.milliseconds();
  return true;
}

int view(ViewSession& session, const Scene& scene, const std::filesystem::path& shader_dir,
         int method, const GlContext& context);

}  // namespace

int run_viewer(ViewSession& session, const Scene& scene, const std::filesystem::path& shader_dir,
               int method, int width, int height) {
  std::string error;
  // Fit the picture on an ordinary screen, keeping the scene's aspect ratio; the panel beside.
  const float shrink = std::min(1.0f, std::min(1600.0f / float(width), 1000.0f / float(height)));
  auto context =
      GlContext::create_window(int(float(width) * shrink) + kPanelWidth,
                               int(float(height) * shrink), "gfield-view " + scene.filename, error);
  if (!context) {
    std::fprintf(stderr, "gfield-view: %s\n", printable(error).c_str());
    return kExitNoOpenGL;
  }
  const int code = view(session, scene, shader_dir, method, *context);
  session.release();  // while the context is current
  return code;
}

namespace {

int view(ViewSession& session, const Scene& scene, const std::filesystem::path& shader_dir,
         int method, const GlContext& context) {
  std::string error;
  ShaderProgram present_program;
  if (!session.load(scene, shader_dir, error) || !session.select(method, error) ||
      !present_program.build(shader_dir, {"fullscreen.vert", "present.frag"}, "", error)) {
    std::fprintf(stderr, "gfield-view: %s\n", printable(error).c_str());
    return 2;
  }
  GLFWwindow* window = context.window();
  ViewerState s;
  s.session = &session;
  s.camera = s.initial_camera = scene.camera;
  glfwSetWindowUserPointer(window, &s);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450");
  glfwSetKeyCallback(window, key_callback);
  Framebuffer frame;
  FrameStats shown;
  double frame_ms = 0.0;
  Stopwatch since_check;
  for (int frame_number = 0; !glfwWindowShouldClose(window);) {
    glfwPollEvents();
    check_shaders(s, since_check);
    if (viewer_frame(window, s, context, present_program, frame, shown, frame_ms, frame_number))
      ++frame_number;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return 0;
}

}  // namespace

}  // namespace gfield
