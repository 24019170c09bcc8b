#pragma once
// JSON reports (nlohmann::json: `gfield info --json`, build reports) as Python objects.

#include <nlohmann/json.hpp>

#include "python/src/bindings.hpp"

namespace gfield::python {

/// objects -> dict, arrays -> list, strings -> str (bytes that are not UTF-8 as \xNN escapes),
/// integers -> int, floats -> float, booleans -> bool, null -> None.
py::object json_to_python(const nlohmann::json& value);

}  // namespace gfield::python
