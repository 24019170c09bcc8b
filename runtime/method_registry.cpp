#include "runtime/method_registry.hpp"

#include "runtime/methods/cube_map.hpp"
#include "runtime/methods/geometry_field.hpp"
#include "runtime/methods/glass.hpp"
#include "runtime/methods/image_space_refraction.hpp"

namespace gfield {

const std::vector<MethodEntry>& method_registry() {
  static const std::vector<MethodEntry> registry = {
      {"field", [] { return std::make_unique<GeometryFieldMethod>(); }},
      {"cubemap", [] { return std::make_unique<CubeMapMethod>(false); }},
      {"envmap", [] { return std::make_unique<CubeMapMethod>(true); }},
      {"wyman2005", [] { return std::make_unique<ImageSpaceRefractionMethod>(false); }},
      {"davis-wyman", [] { return std::make_unique<ImageSpaceRefractionMethod>(true); }},
      {"glass", [] { return std::make_unique<GlassMethod>(); }},
  };
  return registry;
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const MethodEntry& entry : method_registry())
    names.push_back(entry.name);
  return names;
}

std::unique_ptr<Method> make_method(const std::string& name) {
  for (const MethodEntry& entry : method_registry())
    if (entry.name == name)
      return entry.make();
  return nullptr;
}

}  // namespace gfield
