#include "geometry/gltf_extensions.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "gfield/located_json.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

using nlohmann::json;

/// "materials[M] 'NAME'" for a pointer below /materials/M (materials an array), else "".
std::string material_place(const json& document, const std::string& pointer) {
  const std::string prefix = "/materials/";
  if (pointer.rfind(prefix, 0) != 0 || !document["materials"].is_array())
    return "";
  const size_t end = pointer.find('/', prefix.size());
  const std::string index = pointer.substr(prefix.size(), end - prefix.size());
  const json& material = document["materials"][std::stoul(index)];
  const json* name =
      material.is_object() && material.contains("name") ? &material["name"] : nullptr;
  return "materials[" + index + "]" +
         (name != nullptr && name->is_string() ? " '" + name->get<std::string>() + "'" : "");
}

/// Every "extensions" object below `value` (at `pointer`): each member gfield does not implement.
void collect_ignored(const json& value, const std::string& pointer,
                     std::vector<std::pair<std::string, std::string>>& found) {
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) {
      const std::string child = json_pointer_child(pointer, it.key());
      if (it.key() == "extensions" && it.value().is_object()) {
        for (auto e = it.value().begin(); e != it.value().end(); ++e)
          if (!gltf_extension_implemented(e.key()))
            found.emplace_back(json_pointer_child(child, e.key()), e.key());
      }
      if (it.key() != "extras")
        collect_ignored(it.value(), child, found);
    }
  } else if (value.is_array()) {
    for (size_t i = 0; i < value.size(); ++i)
      collect_ignored(value[i], json_pointer_child(pointer, i), found);
  }
}

}  // namespace

const std::vector<std::string>& implemented_gltf_extensions() {
  static const std::vector<std::string> kImplemented = {
      "EXT_meshopt_compression", "KHR_draco_mesh_compression", "KHR_lights_punctual",
      "KHR_materials_ior",       "KHR_materials_transmission", "KHR_materials_volume",
      "KHR_mesh_quantization",   "KHR_texture_transform"};
  return kImplemented;
}

bool gltf_extension_implemented(const std::string& name) {
  const std::vector<std::string>& known = implemented_gltf_extensions();
  return std::binary_search(known.begin(), known.end(), name);
}

bool check_required_extensions(const json& document, JsonFailure& failure) {
  if (!document.contains("extensionsRequired"))
    return true;
  const json& required = document["extensionsRequired"];
  if (!required.is_array()) {
    failure = {"/extensionsRequired", "expected an array of extension names"};
    return false;
  }
  for (size_t i = 0; i < required.size(); ++i) {
    if (required[i].is_string() && gltf_extension_implemented(required[i].get<std::string>()))
      continue;
    std::string list;
    for (const std::string& name : implemented_gltf_extensions())
      list += (list.empty() ? "" : ", ") + name;
    failure = {json_pointer_child("/extensionsRequired", i),
               required[i].is_string()
                   ? "the file requires extension " + required[i].get<std::string>() +
                         ", which gfield does not implement (it implements " + list + ")"
                   : "expected an extension name"};
    return false;
  }
  return true;
}

void ignored_extension_warnings(const std::string& file, const json& document,
                                std::vector<std::string>& warnings) {
  std::vector<std::pair<std::string, std::string>> found;
  collect_ignored(document, "", found);
  std::set<std::string> materials;                        // "PLACE\nNAME" warned
  std::map<std::string, std::vector<std::string>> other;  // name -> pointers
  for (const auto& [pointer, name] : found) {
    const std::string material = material_place(document, pointer);
    if (material.empty())
      other[name].push_back(pointer);
    else if (materials.insert(material + "\n" + name).second)
      warnings.push_back(file + ": " + printable(material) + ": extension " + printable(name) +
                         " is ignored (gfield does not implement it)");
  }
  for (const auto& [name, pointers] : other)
    warnings.push_back(
        file + ": " + printable(pointers.front()) +
        (pointers.size() > 1 ? " (and " + std::to_string(pointers.size() - 1) + " more places)"
                             : "") +
        ": extension " + printable(name) + " is ignored (gfield does not implement it)");
}

}  // namespace gfield
