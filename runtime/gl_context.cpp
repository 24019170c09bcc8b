#include "runtime/gl_context.hpp"

#include <vector>

#include <epoxy/egl.h>
#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace gfield {
namespace {

bool has_extension(const char* list, const std::string& name) {
  if (list == nullptr)
    return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

/// Initialises an EGL display on the device platform, hardware devices first. EGL_NO_DISPLAY
/// when there is no usable device.
EGLDisplay device_display(std::string& chosen) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_EXT_platform_device") ||
      !has_extension(client, "EGL_EXT_device_enumeration"))
    return EGL_NO_DISPLAY;
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0)
    return EGL_NO_DISPLAY;
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  if (!eglQueryDevicesEXT(count, devices.data(), &count))
    return EGL_NO_DISPLAY;
  // Hardware devices (no EGL_MESA_device_software) first, software after.
  std::vector<EGLDeviceEXT> ordered;
  for (int pass = 0; pass < 2; ++pass) {
    for (EGLint i = 0; i < count; ++i) {
      const bool software = has_extension(
          eglQueryDeviceStringEXT(devices[size_t(i)], EGL_EXTENSIONS), "EGL_MESA_device_software");
      if (software == (pass == 1))
        ordered.push_back(devices[size_t(i)]);
    }
  }
  for (EGLDeviceEXT device : ordered) {
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display == EGL_NO_DISPLAY)
      continue;
    EGLint major = 0, minor = 0;
    if (eglInitialize(display, &major, &minor)) {
      const bool software = has_extension(eglQueryDeviceStringEXT(device, EGL_EXTENSIONS),
                                          "EGL_MESA_device_software");
      chosen = software ? "EGL device (software)" : "EGL device";
      return display;
    }
  }
  return EGL_NO_DISPLAY;
}

EGLDisplay surfaceless_display(std::string& chosen) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_MESA_platform_surfaceless"))
    return EGL_NO_DISPLAY;
  EGLDisplay display =
      eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
    return EGL_NO_DISPLAY;
  chosen = "EGL surfaceless";
  return display;
}

}  // namespace

std::unique_ptr<GlContext> GlContext::create_headless(std::string& error) {
  std::unique_ptr<GlContext> context(new GlContext());
  EGLDisplay display = device_display(context->platform_);
  if (display == EGL_NO_DISPLAY)
    display = surfaceless_display(context->platform_);
  if (display == EGL_NO_DISPLAY) {
    error =
        "EGL: no usable display (neither EGL_EXT_platform_device nor "
        "EGL_MESA_platform_surfaceless works)";
    return nullptr;
  }
  context->egl_display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API)) {
    error = "EGL: the display does not support desktop OpenGL";
    return nullptr;
  }
  const char* display_extensions = eglQueryString(display, EGL_EXTENSIONS);
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!has_extension(display_extensions, "EGL_KHR_no_config_context")) {
    const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                 EGL_NONE};
    EGLint found = 0;
    if (!eglChooseConfig(display, attributes, &config, 1, &found) || found < 1) {
      error = "EGL: no OpenGL config on this display";
      return nullptr;
    }
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       4,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       5,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  EGLContext egl_context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (egl_context == EGL_NO_CONTEXT) {
    error = "EGL (" + context->platform_ + "): no OpenGL 4.5 core context available";
    return nullptr;
  }
  context->egl_context_ = egl_context;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_context)) {
    error = "EGL: cannot make the context current without a surface";
    return nullptr;
  }
  if (!context->finish_setup(error))
    return nullptr;
  return context;
}

std::unique_ptr<GlContext> GlContext::create_window(int width, int height, const std::string& title,
                                                    std::string& error) {
  if (!glfwInit()) {
    const char* description = nullptr;
    glfwGetError(&description);
    error = std::string("GLFW: cannot initialise (") + (description ? description : "no display?") +
            "); use --headless";
    return nullptr;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  std::unique_ptr<GlContext> context(new GlContext());
  context->window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (context->window_ == nullptr) {
    const char* description = nullptr;
    glfwGetError(&description);
    error = std::string("GLFW: no OpenGL 4.5 core window (") +
            (description ? description : "unknown reason") + ")";
    return nullptr;
  }
  glfwMakeContextCurrent(context->window_);
  glfwSwapInterval(1);
  context->platform_ = "GLFW";
  if (!context->finish_setup(error))
    return nullptr;
  return context;
}

bool GlContext::finish_setup(std::string& error) {
  if (epoxy_gl_version() < 45) {
    error = "OpenGL 4.5 core is required, the context offers " +
            std::to_string(epoxy_gl_version() / 10) + "." + std::to_string(epoxy_gl_version() % 10);
    return false;
  }
  renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  version_ = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return true;
}

GlContext::~GlContext() {
  if (window_ != nullptr) {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  if (egl_display_ != nullptr) {
    eglMakeCurrent(egl_display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (egl_context_ != nullptr)
      eglDestroyContext(egl_display_, egl_context_);
    eglTerminate(egl_display_);
  }
}

}  // namespace gfield
