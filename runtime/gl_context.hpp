#pragma once
// An OpenGL 4.5 core context: headless through EGL (no X, no surface: render into an FBO) or an
// interactive GLFW window. GL entry points are loaded by libepoxy in both cases.

#include <memory>
#include <string>

struct GLFWwindow;

namespace gfield {

/// Exit code of gfield-view when no OpenGL 4.5 core context can be created.
inline constexpr int kExitNoOpenGL = 3;

class GlContext {
 public:
  /// Headless context: the EGL device platform (EGL_EXT_platform_device), preferring a device
  /// without EGL_MESA_device_software (a hardware GPU) when there is one, else Mesa's surfaceless
  /// platform. Null with an error when no OpenGL 4.5 core context can be made.
  static std::unique_ptr<GlContext> create_headless(std::string& error);
  /// A GLFW window of `width` x `height` screen coordinates with a 4.5 core context, current.
  static std::unique_ptr<GlContext> create_window(int width, int height, const std::string& title,
                                                  std::string& error);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  /// The window, null for a headless context.
  GLFWwindow* window() const { return window_; }
  /// GL_RENDERER, GL_VERSION and how the context was made ("EGL device", "EGL surfaceless",
  /// "GLFW").
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }
  const std::string& platform() const { return platform_; }

 private:
  GlContext() = default;
  bool finish_setup(std::string& error);

  GLFWwindow* window_ = nullptr;
  void* egl_display_ = nullptr;
  void* egl_context_ = nullptr;
  std::string renderer_;
  std::string version_;
  std::string platform_;
};

}  // namespace gfield
