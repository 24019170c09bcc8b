#pragma once
// The glTF 2.0 extensions gfield implements, and what it does with the others (docs/scenes.md,
// "glTF features"): a file whose extensionsRequired names one that gfield does not implement is
// refused, as the specification asks of a loader; one that is used but not required is ignored,
// with a warning that names where it is used (a material by its index and name). Internal to the
// glTF code.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/gltf_checks.hpp"

namespace gfield {

/// The extensions gfield implements, sorted by name.
const std::vector<std::string>& implemented_gltf_extensions();

/// True when `name` is one of implemented_gltf_extensions().
bool gltf_extension_implemented(const std::string& name);

/// The document's extensionsRequired: false with `failure` at "/extensionsRequired/I" for the
/// first entry that is not a string or names an extension gfield does not implement.
bool check_required_extensions(const nlohmann::json& document, JsonFailure& failure);

/// Appends a warning for every place of `document` (glTF file `file`) that uses an extension
/// gfield does not implement: "FILE: materials[M] 'NAME': extension X is ignored (...)" below a
/// material, "FILE: /POINTER: extension X is ignored (...)" elsewhere.
void ignored_extension_warnings(const std::string& file, const nlohmann::json& document,
                                std::vector<std::string>& warnings);

}  // namespace gfield
