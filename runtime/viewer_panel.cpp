#include "runtime/viewer_panel.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <imgui.h>

#include "gfield/image.hpp"
#include "gfield/optics.hpp"
#include "runtime/asset_memory.hpp"
#include "runtime/method_panel.hpp"
#include "runtime/viewer.hpp"
#include "runtime/viewer_input.hpp"

namespace gfield {
namespace {

/// A combo of the session's methods; `with_off` adds "(off)" (-1). The index chosen.
int method_combo(ViewSession& session, const char* label, int current, bool with_off) {
  int choice = current;
  const std::string preview = current >= 0 ? session.method(current).info().title : "(off)";
  if (ImGui::BeginCombo(label, preview.c_str())) {
    if (with_off && ImGui::Selectable("(off)", current < 0))
      choice = -1;
    for (int k = 0; k < session.method_count(); ++k)
      if (ImGui::Selectable(session.method(k).info().title.c_str(), k == current))
        choice = k;
    ImGui::EndCombo();
  }
  return choice;
}

void methods_section(ViewerState& s) {
  ViewSession& session = *s.session;
  const int method = method_combo(session, "method", session.current(), false);
  if (method != session.current())
    request_method_switch(s, false, false, method);
  const int compare = method_combo(session, "right half", session.compare(), true);
  if (compare != session.compare())
    request_method_switch(s, true, false, compare);
  if (!s.message.empty())  // here, where a small window shows it too
    ImGui::TextWrapped("%s", s.message.c_str());
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
      session.set_reference(std::move(reference), s.reference_path);
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

void figures_section(ViewerState& s, const GlContext& context, const PictureFigures& figures) {
  ImGui::Text("%s", context.renderer().c_str());
  ImGui::Text("picture %.1f ms; window %.0f FPS", figures.render_ms,
              1000.0 / std::max(figures.window_ms, 1e-3));
  for (const auto& [name, value] : figures.stats.counts)
    ImGui::Text("%s %.0f", name.c_str(), value);
  const std::string status = s.session->method(s.session->current()).status();
  if (!status.empty())
    ImGui::TextWrapped("%s", status.c_str());
  const GpuScene& scene = s.session->scene();
  ImGui::Text("texture memory %.1f MB", double(scene.assets().texture_bytes()) / 1e6);
  ImGui::TextUnformatted(asset_memory_lines(scene.scene(), scene.assets()).c_str());
}

}  // namespace

void viewer_panel(ViewerState& s, const GlContext& context, const PictureFigures& figures,
                  int window_width, int window_height) {
  ImGui::SetNextWindowPos(ImVec2(float(window_width - kPanelWidth), 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(float(kPanelWidth), float(window_height)), ImGuiCond_Always);
  ImGui::Begin("gfield-view", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  methods_section(s);  // first: the combos stay where they are whatever the figures say
  ImGui::Separator();
  figures_section(s, context, figures);
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
  if (!s.shader_error.empty())
    ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", s.shader_error.c_str());
  if (ImGui::CollapsingHeader("shortcuts"))
    ImGui::TextUnformatted(viewer_shortcuts());
  ImGui::End();
}

}  // namespace gfield
