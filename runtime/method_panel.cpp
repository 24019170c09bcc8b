#include "runtime/method_panel.hpp"

#include <imgui.h>

namespace gfield {
namespace {

bool option_control(const MethodOption& o) {
  switch (o.kind) {
    case MethodOption::Kind::kInt:
      return ImGui::SliderInt(o.label.c_str(), o.int_value, int(o.min), int(o.max));
    case MethodOption::Kind::kFloat:
      return ImGui::SliderFloat(o.label.c_str(), o.float_value, float(o.min), float(o.max), "%.3f");
    case MethodOption::Kind::kFlag:
      return ImGui::Checkbox(o.label.c_str(), o.flag_value);
    case MethodOption::Kind::kChoice: {
      int index = o.get_choice();
      std::vector<const char*> names;
      for (const std::string& c : o.choices)
        names.push_back(c.c_str());
      if (!ImGui::Combo(o.label.c_str(), &index, names.data(), int(names.size())))
        return false;
      o.set_choice(index);
      return true;
    }
  }
  return false;
}

}  // namespace

bool method_panel(Method& method) {
  bool changed = false;
  ImGui::PushID(method.info().name.c_str());
  for (const MethodOption& o : method.options()) {
    changed |= option_control(o);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("--%s: %s", o.name.c_str(), o.help.c_str());
  }
  ImGui::PopID();
  return changed;
}

}  // namespace gfield
