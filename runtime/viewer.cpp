#include "runtime/viewer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "gfield/optics.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/gpu_scene.hpp"
#include "runtime/methods/glass_view.hpp"
#include "runtime/methods/image_space_view.hpp"

namespace gfield {

const char* viewer_shortcuts() {
  return "  left drag          orbit the camera around its target\n"
         "  right drag         pan (shift + left drag too)\n"
         "  wheel              zoom (move towards the target)\n"
         "  left click         select the object under the cursor (click empty space: none)\n"
         "  ctrl + left drag   move the selected object in the view plane\n"
         "  page up / down     move the selected object towards / away from the camera\n"
         "  1 / 2 / 3          lookup mode nearest / linear / refined\n"
         "  + / -              recursion depth up / down\n"
         "  f                  self-reflection on / off\n"
         "  r                  reload the shaders now (they also reload when their files change)\n"
         "  p                  screenshot: gfield-view-N.png in the current folder\n"
         "  c                  camera back to the scene's\n"
         "  h                  hide / show the panel\n"
         "  esc                quit\n";
}

namespace {

struct ViewerState {
  Renderer* renderer = nullptr;
  RenderSettings settings;
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
  ImageSpaceView image_space;
  GlassView glass;
};

/// World ray through window coordinates (x right, y down, in framebuffer pixels).
void pixel_ray(const Camera& camera, int width, int height, double x, double y, glm::vec3& origin,
               glm::vec3& direction) {
  const CameraRay ray = camera_ray(camera, width, height, glm::dvec2(x, y));
  origin = glm::vec3(ray.origin);
  direction = glm::vec3(ray.direction);
}

/// The object whose world bounds the ray enters first (a cheap pick), or -1.
int pick(const Renderer& renderer, glm::vec3 origin, glm::vec3 direction) {
  int best = -1;
  float best_t = 3.0e38f;
  for (int k = 0; k < int(renderer.scene().objects.size()); ++k) {
    glm::vec3 lo, hi;
    object_world_bounds(renderer.scene(), renderer.assets(), k, lo, hi);
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

void key_callback(GLFWwindow* window, int key, int scancode, int action, int mods) {
  ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
  if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard)
    return;
  auto* s = static_cast<ViewerState*>(glfwGetWindowUserPointer(window));
  Scene& scene = s->renderer->scene();
  switch (key) {
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(window, GLFW_TRUE);
      break;
    case GLFW_KEY_1:
      s->settings.mode = LookupMode::kNearest;
      break;
    case GLFW_KEY_2:
      s->settings.mode = LookupMode::kLinear;
      break;
    case GLFW_KEY_3:
      s->settings.mode = LookupMode::kRefined;
      break;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
      s->settings.max_depth = std::min(s->settings.max_depth + 1, 64);
      break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      s->settings.max_depth = std::max(s->settings.max_depth - 1, 0);
      break;
    case GLFW_KEY_F:
      s->settings.self_reflection = !s->settings.self_reflection;
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
        t += (key == GLFW_KEY_PAGE_UP ? 0.05f : -0.05f) * s->renderer->scene_extent() * towards;
        s->renderer->update_scene();
      }
      break;
    default:
      break;
  }
}

void panel(ViewerState& s, const GlContext& context, const FrameStats& stats, double frame_ms) {
  Scene& scene = s.renderer->scene();
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("gfield-view");
  ImGui::Text("%s", context.renderer().c_str());
  ImGui::Text("frame %.1f ms (%.1f FPS)", frame_ms, 1000.0 / std::max(frame_ms, 1e-3));
  ImGui::Text("traced pixels %lld, secondary rays %lld", stats.traced_pixels, stats.secondary_rays);
  ImGui::Separator();
  const char* methods[] = {"geometry field (Li et al. 2006)"};
  int method = 0;
  ImGui::Combo("method", &method, methods, 1);
  image_space_panel(s.image_space);
  glass_panel(s.glass);
  int mode = int(s.settings.mode);
  const char* modes[] = {"nearest", "linear", "refined"};
  if (ImGui::Combo("lookup", &mode, modes, 3))
    s.settings.mode = LookupMode(mode);
  ImGui::SliderInt("depth", &s.settings.max_depth, 0, 16);
  ImGui::Checkbox("self-reflection", &s.settings.self_reflection);
  ImGui::SliderFloat("min weight", &s.settings.min_weight, 0.0f, 0.1f, "%.3f");
  ImGui::SliderInt("max rays / pixel", &s.settings.max_rays, 1, 64);
  ImGui::Separator();
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
  if (s.selected >= 0) {
    SceneObject& o = scene.objects[size_t(s.selected)];
    bool changed = false;
    changed |= ImGui::DragFloat3("translate", &o.transform.translate.x, 0.01f);
    changed |= ImGui::DragFloat3("rotate", &o.transform.rotate_degrees.x, 0.5f);
    int type = int(o.material.type);
    const char* types[] = {"diffuse", "mirror", "dielectric"};
    const int type_count = shape_is_closed(o.shape.type) ? 3 : 2;
    if (ImGui::Combo("material", &type, types, type_count)) {
      o.material.type = MaterialType(type);
      changed = true;
    }
    if (o.material.type != MaterialType::kDielectric)
      changed |= ImGui::ColorEdit3(o.material.type == MaterialType::kMirror ? "tint" : "colour",
                                   &o.material.color.x);
    if (o.material.type == MaterialType::kDielectric) {
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
      changed |= ImGui::ColorEdit3("absorption", &o.material.absorption.x,
                                   ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    }
    if (changed)
      s.renderer->update_scene();
  }
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

}  // namespace

int run_viewer(const Scene& scene, const std::filesystem::path& shader_dir,
               const RenderSettings& settings, int width, int height) {
  std::string error;
  // Fit the window on an ordinary screen, keeping the scene's aspect ratio.
  const float shrink = std::min(1.0f, std::min(1600.0f / float(width), 1000.0f / float(height)));
  auto context = GlContext::create_window(int(float(width) * shrink), int(float(height) * shrink),
                                          "gfield-view " + scene.filename, error);
  if (!context) {
    std::fprintf(stderr, "gfield-view: %s\n", error.c_str());
    return kExitNoOpenGL;
  }
  Renderer renderer;
  if (!renderer.load(scene, shader_dir, error)) {
    std::fprintf(stderr, "gfield-view: %s\n", error.c_str());
    return 2;
  }
  ShaderProgram present;
  if (!present.build(shader_dir, {"fullscreen.vert", "present.frag"}, "", error)) {
    std::fprintf(stderr, "gfield-view: %s\n", error.c_str());
    return 2;
  }
  GLFWwindow* window = context->window();
  ViewerState s;
  s.renderer = &renderer;
  s.settings = settings;
  s.camera = s.initial_camera = scene.camera;
  s.image_space.shader_dir = shader_dir;
  s.glass.shader_dir = shader_dir;
  glfwSetWindowUserPointer(window, &s);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450");
  glfwSetKeyCallback(window, key_callback);

  Framebuffer frame;
  GLuint empty_vertex_array = 0;
  glCreateVertexArrays(1, &empty_vertex_array);
  FrameStats shown;
  double frame_ms = 0.0;
  int frame_number = 0, screenshot_number = 0;
  auto last_reload_check = std::chrono::steady_clock::now();
  while (!glfwWindowShouldClose(window)) {
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    int fb_width = 0, fb_height = 0, win_width = 0, win_height = 0;
    glfwGetFramebufferSize(window, &fb_width, &fb_height);
    glfwGetWindowSize(window, &win_width, &win_height);
    if (fb_width <= 0 || fb_height <= 0)
      continue;
    const float scale = float(fb_width) / float(std::max(win_width, 1));

    // Mouse: orbit, pan, zoom, select, move.
    const ImGuiIO& io = ImGui::GetIO();
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    const float dx = float(x - s.last_x), dy = float(y - s.last_y);
    if (!io.WantCaptureMouse) {
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
        if (s.drag_moves_object) {
          glm::vec3& t = renderer.scene().objects[size_t(s.selected)].transform.translate;
          t += screen_offset(s.camera, win_height, t, dx, dy);
          renderer.update_scene();
        } else if (s.drag_button == 1 || shift) {
          const glm::vec3 offset = screen_offset(s.camera, win_height, s.camera.target, -dx, -dy);
          s.camera.position += offset;
          s.camera.target += offset;
        } else {
          orbit(s.camera, dx, dy);
        }
      } else if (s.dragging) {
        // Released: a click without movement selects.
        if (s.drag_button == 0 && std::abs(x - s.press_x) + std::abs(y - s.press_y) < 3.0) {
          glm::vec3 origin, direction;
          pixel_ray(s.camera, fb_width, fb_height, x * scale, y * scale, origin, direction);
          s.selected = pick(renderer, origin, direction);
        }
        s.dragging = false;
      }
      if (io.MouseWheel != 0.0f) {
        const glm::vec3 offset = s.camera.position - s.camera.target;
        s.camera.position = s.camera.target + offset * std::pow(0.9f, io.MouseWheel);
      }
    }
    s.last_x = x;
    s.last_y = y;

    // Shaders: reload on request or when a file changed (checked twice a second).
    const auto now = std::chrono::steady_clock::now();
    if (s.reload || now - last_reload_check > std::chrono::milliseconds(500)) {
      std::string reload_error;
      const bool rebuilt = renderer.reload_shaders_if_changed(reload_error);
      if (!reload_error.empty()) {
        s.shader_error = reload_error;
        std::fprintf(stderr, "gfield-view: %s\n", reload_error.c_str());
      } else if (rebuilt) {
        s.shader_error.clear();
        s.message = "shaders reloaded";
      }
      s.reload = false;
      last_reload_check = now;
    }

    frame.resize(fb_width, fb_height);
    const auto start = std::chrono::steady_clock::now();
    FrameStats stats;
    // Counting traced pixels reads the hit buffer back: every 30 frames.
    const bool count = frame_number % 30 == 0;
    if (!glass_draw(s.glass, renderer.scene(), s.camera, frame))
      image_space_draw(s.image_space, renderer, s.camera, s.settings, frame,
                       count ? &stats : nullptr);
    if (count)
      shown = stats;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb_width, fb_height);
    glUseProgram(present.id());
    glBindTextureUnit(0, frame.color_texture());
    glBindVertexArray(empty_vertex_array);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (s.screenshot) {
      const RgbaImage pixels = frame.read();
      Image image(pixels.width, pixels.height);
      for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = glm::vec3(pixels.pixels[i]);
      const std::string name = "gfield-view-" + std::to_string(screenshot_number++) + ".png";
      std::string save_error;
      s.message = save_image(name, image, save_error) ? "saved " + name : save_error;
      s.screenshot = false;
    }
    if (s.show_panel)
      panel(s, *context, shown, frame_ms);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window);
    glFinish();
    frame_ms = 0.9 * frame_ms + 0.1 * std::chrono::duration<double, std::milli>(
                                          std::chrono::steady_clock::now() - start)
                                          .count();
    ++frame_number;
  }
  glDeleteVertexArrays(1, &empty_vertex_array);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return 0;
}

}  // namespace gfield
