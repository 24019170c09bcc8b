#include "runtime/viewer.hpp"

#include <algorithm>
#include <cstdio>
#include <regex>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "gfield/camera_text.hpp"
#include "gfield/gpu_contract.hpp"
#include "gfield/printable.hpp"
#include "gfield/stopwatch.hpp"
#include "runtime/method_cli.hpp"
#include "runtime/viewer_input.hpp"
#include "runtime/viewer_panel.hpp"
#include "runtime/viewer_state.hpp"

namespace gfield {
namespace {

/// Everything the picture depends on, as text: the picture is rendered again only when it
/// changes (an idle viewer presents the last picture and costs nothing).
std::string picture_key(ViewSession& session, const Camera& camera, int width, int height) {
  std::string key = camera_text(camera) + " " + std::to_string(width) + "x" +
                    std::to_string(height) + " revision " + std::to_string(session.revision()) +
                    " difference " + std::to_string(session.difference) + " " +
                    std::to_string(session.difference_scale);
  for (int method : {session.current(), session.compare()})
    key += " | " + std::to_string(method) +
           (method >= 0 ? " " + option_arguments(session.method(method)) : "");
  return key;
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

/// The first N for which no gfield-view-N.png is in the current folder at or after any there.
int next_screenshot_number() {
  static const std::regex pattern(R"(gfield-view-(\d{1,9})\.png)");
  int next = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(".", ec)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, match, pattern))
      next = std::max(next, std::stoi(match[1].str()) + 1);
  }
  return next;
}

/// Saves the picture as gfield-view-N.png and prints how to render it headless.
void save_screenshot(ViewerState& s, const Framebuffer& frame) {
  s.screenshot = false;
  const std::string name = "gfield-view-" + std::to_string(next_screenshot_number()) + ".png";
  std::string error;
  if (!save_image(name, frame.read_image(), error)) {
    s.message = error;
    std::fprintf(stderr, "gfield-view: %s\n", printable(error).c_str());
    return;
  }
  ViewSession& session = *s.session;
  std::string line = "saved " + name + "; headless: " + s.command + " --headless --size " +
                     std::to_string(frame.width()) + "x" + std::to_string(frame.height()) +
                     " --method " + session.method(session.current()).info().name + " " +
                     option_arguments(session.method(session.current())) + " --camera " +
                     camera_text(s.camera) + " -o " + name;
  if (session.compare() >= 0)
    line += "; right half: --method " + session.method(session.compare()).info().name + " " +
            option_arguments(session.method(session.compare()));
  std::printf("gfield-view: %s\n", printable(line).c_str());
  std::fflush(stdout);
  s.message = "saved " + name + " (the command that renders it headless is on stdout)";
}

/// Shows the picture in the left frame.width() framebuffer pixels of the window: the state it
/// needs is set here, whatever the methods left (depth test, blending, culling, scissor).
void present(ViewSession& session, const ShaderProgram& program, const Framebuffer& frame,
             int window_width, int window_height) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glViewport(0, 0, window_width, window_height);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glViewport(0, 0, frame.width(), frame.height());
  glUseProgram(program.id());
  glBindTextureUnit(gpu::UNIT_FRAME, frame.color_texture());
  session.scene().draw_fullscreen();
}

/// The frame loop's state besides the viewer's.
struct Window {
  GLFWwindow* glfw = nullptr;
  const GlContext* context = nullptr;
  const ShaderProgram* present_program = nullptr;
  Framebuffer frame;
  PictureFigures figures;
  std::string drawn;  ///< picture_key of the picture in `frame`
};

/// One iteration of the window's loop: renders the picture if anything it depends on changed,
/// presents it and the panel. True when the picture was rendered.
bool viewer_frame(ViewerState& s, Window& w) {
  int fb_width = 0, fb_height = 0, win_width = 0, win_height = 0;
  glfwGetFramebufferSize(w.glfw, &fb_width, &fb_height);
  glfwGetWindowSize(w.glfw, &win_width, &win_height);
  if (fb_width <= 0 || fb_height <= 0)
    return false;
  const Stopwatch clock;
  s.scale = float(fb_width) / float(std::max(win_width, 1));
  s.picture_width = std::max(1, win_width - (s.show_panel ? kPanelWidth : 0));
  s.picture_height = win_height;
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  w.frame.resize(std::max(1, int(float(s.picture_width) * s.scale)), fb_height);
  const std::string key = picture_key(*s.session, s.camera, w.frame.width(), w.frame.height());
  bool measuring = false;  // a method timing itself wants the same picture again
  for (int method : {s.session->current(), s.session->compare()})
    measuring = measuring || (method >= 0 && s.session->method(method).measuring());
  const bool render = key != w.drawn || measuring;
  if (render) {
    FrameStats stats;
    s.session->draw(s.camera, w.frame, &stats);
    w.figures.stats = stats;
    w.figures.render_ms = clock.milliseconds();
    w.drawn = key;
  }
  present(*s.session, *w.present_program, w.frame, fb_width, fb_height);
  if (s.screenshot)
    save_screenshot(s, w.frame);
  if (s.show_panel)
    viewer_panel(s, *w.context, w.figures, win_width, win_height);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(w.glfw);
  glFinish();
  w.figures.window_ms = 0.9 * w.figures.window_ms + 0.1 * clock.milliseconds();
  return render;
}

int view(ViewSession& session, const Scene& scene, const std::filesystem::path& shader_dir,
         const ViewerOptions& options, const GlContext& context) {
  std::string error;
  ShaderProgram present_program;
  if (!session.load(scene, shader_dir, error) || !session.select(options.method, error) ||
      !present_program.build(shader_dir, {"fullscreen.vert", "present.frag"}, "", error)) {
    std::fprintf(stderr, "gfield-view: %s\n", printable(error).c_str());
    return 2;
  }
  ViewerState s;
  s.session = &session;
  s.camera = s.initial_camera = scene.camera;
  s.command = options.command;
  Window w;
  w.glfw = context.window();
  w.context = &context;
  w.present_program = &present_program;
  glfwSetWindowUserPointer(w.glfw, &s);
  install_input_callbacks(w.glfw);  // before ImGui's, which call them first
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 1.0f;  // docked beside the picture: opaque
  ImGui_ImplGlfw_InitForOpenGL(w.glfw, true);
  ImGui_ImplOpenGL3_Init("#version 450");
  Stopwatch since_check;
  // An idle viewer (no input, nothing to render for a few frames) sleeps until an event comes,
  // waking twice a second to look for changed shader files.
  for (int idle_frames = 0; !glfwWindowShouldClose(w.glfw);) {
    if (idle_frames >= 3)
      glfwWaitEventsTimeout(0.5);
    else
      glfwPollEvents();
    if (s.input)
      idle_frames = 0;
    s.input = false;
    check_shaders(s, since_check);
    switch_method_if_due(s);
    idle_frames = viewer_frame(s, w) ? 0 : idle_frames + 1;
    if (s.method_switch.pending) {
      ++s.method_switch.frames_shown;
      idle_frames = 0;
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return 0;
}

}  // namespace

int run_viewer(ViewSession& session, const Scene& scene, const std::filesystem::path& shader_dir,
               const ViewerOptions& options) {
  std::string error;
  // Fit the picture on an ordinary screen, keeping the scene's aspect ratio; the panel beside.
  const float shrink =
      std::min(1.0f, std::min(1600.0f / float(options.width), 1000.0f / float(options.height)));
  auto context = GlContext::create_window(int(float(options.width) * shrink) + kPanelWidth,
                                          int(float(options.height) * shrink),
                                          "gfield-view " + scene.filename, error);
  if (!context) {
    std::fprintf(stderr, "gfield-view: %s\n", printable(error).c_str());
    return kExitNoOpenGL;
  }
  const int code = view(session, scene, shader_dir, options, *context);
  session.release();  // while the context is current
  return code;
}

}  // namespace gfield
