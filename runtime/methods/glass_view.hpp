#pragma once
// The glass method (runtime/methods/glass.hpp) inside the interactive gfield-view window: a
// switch in the panel and the frame drawn by it while on. Header-only: it uses Dear ImGui, which
// only the gfield-view executable links. The glass method draws the scene as loaded.

#include <filesystem>
#include <memory>
#include <string>

#include <imgui.h>

#include "gfield/scene.hpp"
#include "runtime/framebuffer.hpp"
#include "runtime/methods/glass.hpp"

namespace gfield {

struct GlassView {
  std::filesystem::path shader_dir;
  std::unique_ptr<GlassRenderer> renderer;
  bool enabled = false;
  GlassSettings settings;
  std::string message;
};

/// The method's switch and settings; call inside the panel window.
inline void glass_panel(GlassView& v) {
  ImGui::Checkbox("glass by vertex displacement (Mukai et al. 2013)", &v.enabled);
  if (v.enabled) {
    ImGui::Checkbox("Fresnel at the glass", &v.settings.fresnel);
    ImGui::SameLine();
    ImGui::Checkbox("trace the verge", &v.settings.trace_verge);
  }
  if (!v.message.empty())
    ImGui::TextWrapped("%s", v.message.c_str());
}

/// Draws `camera`'s frame with the glass method when it is on (loading it the first time).
/// False when it did not draw: off, or the scene has no glass it can draw (the message says why
/// and the switch goes off).
inline bool glass_draw(GlassView& v, const Scene& scene, const Camera& camera, Framebuffer& frame) {
  if (!v.enabled)
    return false;
  if (!v.renderer) {
    auto renderer = std::make_unique<GlassRenderer>();
    std::string error;
    if (!renderer->load(scene, v.shader_dir, v.settings, error)) {
      v.message = error;
      v.enabled = false;
      return false;
    }
    v.renderer = std::move(renderer);
    v.message.clear();
  }
  v.renderer->render(camera, v.settings, frame);
  return true;
}

}  // namespace gfield
