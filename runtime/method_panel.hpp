#pragma once
// A method's options as Dear ImGui controls (sliders, checkboxes, combos), made from its
// MethodOption descriptions. Compiled into gfield-view (Dear ImGui).

#include "runtime/method.hpp"

namespace gfield {

/// Shows `method`'s options inside the current ImGui window; true when one changed.
bool method_panel(Method& method);

}  // namespace gfield
