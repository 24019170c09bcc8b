#pragma once
// The one list of gfield-view's methods: `--method`, `--help`, the headless path and the
// viewer's method menu all come from it. A new method is one line in method_registry.cpp.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "runtime/method.hpp"

namespace gfield {

struct MethodEntry {
  std::string name;  ///< equals make()->info().name
  std::function<std::unique_ptr<Method>()> make;
};

/// Every method, in the order menus show them (the geometry field first).
const std::vector<MethodEntry>& method_registry();
/// The registry's names.
std::vector<std::string> method_names();
/// A new method by name; null when no method has that name.
std::unique_ptr<Method> make_method(const std::string& name);

}  // namespace gfield
