#pragma once
// A strict JSON parser (RFC 8259) that remembers where every value starts, so that validation
// errors can say "FILE:LINE:COLUMN: problem". nlohmann::json holds the values; the locations are
// keyed by JSON pointer ("" is the root, "/objects/2/material" a nested value).

#include <string>
#include <unordered_map>

#include <nlohmann/json.hpp>

namespace gfield {

/// 1-based line and column (columns count bytes).
struct JsonLocation {
  int line = 0;
  int column = 0;
};

struct LocatedJson {
  nlohmann::json value;
  std::unordered_map<std::string, JsonLocation> locations;

  /// Where the value at `pointer` starts; for a pointer that names no value (a missing key), the
  /// location of its nearest existing ancestor.
  JsonLocation at(const std::string& pointer) const;
};

/// What is wrong in a JSON document (a scene, a glTF file) and where: a JSON pointer into it,
/// which LocatedJson::at turns into a line and column. (Text formats read line by line say where
/// by a line: ReadFailure, geometry/mesh_readers.hpp.)
struct JsonFailure {
  std::string pointer;
  std::string what;
};

/// Parses `text`. On failure returns false with `error` = "LINE:COLUMN: problem".
/// Duplicate keys, non-finite numbers (e.g. 1e999), trailing text and nesting deeper than
/// kMaxJsonDepth (gfield/limits.hpp) are errors.
bool parse_located_json(const std::string& text, LocatedJson& out, std::string& error);

/// `pointer` + "/" + `key` with JSON pointer escaping (~ -> ~0, / -> ~1).
std::string json_pointer_child(const std::string& pointer, const std::string& key);
std::string json_pointer_child(const std::string& pointer, size_t index);

}  // namespace gfield
