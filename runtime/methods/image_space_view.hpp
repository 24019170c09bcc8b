#pragma once
// The image-space methods inside the interactive gfield-view window (runtime/viewer.cpp): their
// menu and settings, a split view of two methods (left half: the chosen method, right half: the
// second one) and the difference against a reference picture as an error heat map.
// Header-only: it uses Dear ImGui, which only the gfield-view executable links.

#include <filesystem>
#include <memory>
#include <string>

#include <imgui.h>

#include "gfield/image.hpp"
#include "gfield/image_metrics.hpp"
#include "runtime/framebuffer.hpp"
#include "runtime/methods/image_space.hpp"
#include "runtime/renderer.hpp"

namespace gfield {

struct ImageSpaceView {
  std::filesystem::path shader_dir;
  std::unique_ptr<ImageSpaceRenderer> renderer;
  std::string message;
  int method = 0;   ///< 0: the geometry field; k: image-space method k - 1
  int compare = 0;  ///< right half: 0 off, 1 the geometry field, k + 1: image-space method k - 1
  int background = 0;
  ImageSpaceSettings settings;
  bool difference = false;
  float difference_scale = 0.25f;
  char reference_path[512] = "";
  Image reference;
  Framebuffer second;
};

inline const char* const* image_space_view_methods() {
  static const char* const names[] = {"geometry field (Li et al. 2006)", "cubemap (Hurley)",
                                      "envmap (cube-map reflection)", "wyman2005 (two-sided)",
                                      "davis-wyman (TIR, Davis & Wyman 2007)"};
  return names;
}

/// The method menu and the settings of the chosen methods; call inside the panel window.
inline void image_space_panel(ImageSpaceView& v) {
  ImGui::Combo("rendering", &v.method, image_space_view_methods(), 5);
  const char* compares[] = {"(off)",  "geometry field", "cubemap",
                            "envmap", "wyman2005",      "davis-wyman"};
  ImGui::Combo("right half", &v.compare, compares, 6);
  const auto uses = [&](ImageSpaceMethod m) {
    return v.method == int(m) + 1 || v.compare == int(m) + 2;
  };
  ImageSpaceSettings& s = v.settings;
  if (uses(ImageSpaceMethod::kCubeMap) || uses(ImageSpaceMethod::kEnvMap)) {
    ImGui::SliderInt("cube size", &s.cube_size, 16, 1024);
    ImGui::Checkbox("per-vertex vector (Hurley)", &s.per_vertex);
    ImGui::SameLine();
    ImGui::Checkbox("Fresnel", &s.fresnel);
  }
  if (uses(ImageSpaceMethod::kWyman2005) || uses(ImageSpaceMethod::kDavisWyman)) {
    ImGui::SliderInt("bounces", &s.bounces, 0, 8);
    ImGui::SliderInt("steps, first ray", &s.iterations_first, 0, 16);
    ImGui::SliderInt("steps, later rays", &s.iterations_later, 0, 16);
    ImGui::SliderInt("steps, nearby geometry", &s.exit_iterations, 0, 16);
    ImGui::Checkbox("back faces only after the first", &s.back_only_later);
    ImGui::SliderFloat("buffer scale", &s.buffer_scale, 0.0625f, 1.0f);
    ImGui::SliderFloat("min alignment", &s.min_alignment, 0.5f, 1.0f, "%.3f");
    const char* backgrounds[] = {"nearby-geometry depth map", "analytic shapes"};
    ImGui::Combo("leaving rays", &v.background, backgrounds, 2);
    s.background = ExitBackground(v.background);
  }
  ImGui::InputText("reference .exr", v.reference_path, sizeof(v.reference_path));
  ImGui::SameLine();
  if (ImGui::Button("load")) {
    std::string error;
    v.message = load_image(v.reference_path, v.reference, error)
                    ? std::string("reference ") + v.reference_path
                    : error;
  }
  ImGui::Checkbox("difference to reference", &v.difference);
  ImGui::SameLine();
  ImGui::SliderFloat("white at", &v.difference_scale, 0.01f, 1.0f, "%.2f");
  if (!v.message.empty())
    ImGui::TextWrapped("%s", v.message.c_str());
}

/// Draws one frame into `frame`: the chosen method, the second one on the right half, and, when
/// asked and a reference of the frame's size is loaded, the error heat map instead.
inline void image_space_draw(ImageSpaceView& v, Renderer& field, const Camera& camera,
                             const RenderSettings& settings, Framebuffer& frame,
                             FrameStats* stats) {
  const bool needs_image_space = v.method > 0 || v.compare > 1;
  if (needs_image_space && !v.renderer) {
    v.renderer = std::make_unique<ImageSpaceRenderer>();
    std::string error;
    if (!v.renderer->load(field.scene(), v.shader_dir, error)) {
      v.message = error;
      v.renderer.reset();
      v.method = v.compare = 0;
    }
  }
  const auto draw = [&](int method, Framebuffer& target, FrameStats* s) {
    if (method == 0 || !v.renderer) {
      field.render(camera, settings, target, glm::vec2(0.0f), s);
      return;
    }
    ImageSpaceSettings is = v.settings;
    is.method = ImageSpaceMethod(method - 1);
    std::string error;
    if (!v.renderer->supports(is.method, error)) {
      v.message = error;
      is.method = ImageSpaceMethod::kDavisWyman;
    }
    v.renderer->scene() = field.scene();
    v.renderer->update_scene();
    v.renderer->render(camera, is, target);
  };
  draw(v.method, frame, stats);
  if (v.compare > 0) {
    v.second.resize(frame.width(), frame.height());
    draw(v.compare - 1, v.second, nullptr);
    const int half = frame.width() / 2;
    glBlitNamedFramebuffer(v.second.framebuffer(), frame.framebuffer(), half, 0, frame.width(),
                           frame.height(), half, 0, frame.width(), frame.height(),
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  if (v.difference && v.reference.width == frame.width() && v.reference.height == frame.height()) {
    const RgbaImage pixels = frame.read();
    Image image(pixels.width, pixels.height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      image.pixels[i] = glm::vec3(pixels.pixels[i]);
    const ImageComparison c = compare_images(image, v.reference);
    v.message = "PSNR " + std::to_string(c.psnr).substr(0, 5) + " dB against the reference";
    const Image heat = error_heatmap(image, v.reference, v.difference_scale);
    // Upload bottom row first (the frame's layout) and copy over the frame.
    std::vector<glm::vec4> rows(heat.pixels.size());
    for (int y = 0; y < heat.height; ++y)
      for (int x = 0; x < heat.width; ++x)
        rows[size_t(heat.height - 1 - y) * size_t(heat.width) + size_t(x)] =
            glm::vec4(heat.at(x, y), 1.0f);
    glTextureSubImage2D(frame.color_texture(), 0, 0, 0, heat.width, heat.height, GL_RGBA, GL_FLOAT,
                        rows.data());
  } else if (v.difference) {
    v.message = "difference: load a reference of " + std::to_string(frame.width()) + "x" +
                std::to_string(frame.height()) + " (e.g. gfield render SCENE --size WxH)";
  }
}

}  // namespace gfield
