#include "scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "gfield/limits.hpp"
#include "gfield/located_json.hpp"
#include "gfield/printable.hpp"

namespace gfield {

namespace fs = std::filesystem;
using nlohmann::json;

/// "/objects/2/material" -> "objects[2].material".
std::string readable_path(const std::string& pointer) {
  std::string out;
  size_t i = 0;
  while (i < pointer.size()) {
    const size_t next = pointer.find('/', i + 1);
    std::string token =
        pointer.substr(i + 1, next == std::string::npos ? std::string::npos : next - i - 1);
    const bool index = !token.empty() && std::all_of(token.begin(), token.end(), ::isdigit);
    if (index) {
      out += "[" + token + "]";
    } else {
      out += (out.empty() ? "" : ".") + token;
    }
    if (next == std::string::npos)
      break;
    i = next;
  }
  return out;
}

std::string list_names(std::initializer_list<const char*> names) {
  std::string out;
  size_t k = 0;
  for (const char* n : names) {
    if (k > 0)
      out += (k + 1 == names.size()) ? " or " : ", ";
    out += n;
    ++k;
  }
  return out;
}

SceneReader::SceneReader(const json& root, fs::path base, fs::path files_root, OutsidePaths outside)
    : root_(root), base_(std::move(base)), files_root_(std::move(files_root)), outside_(outside) {}

const json& SceneReader::at(const std::string& pointer) const {
  return root_.at(json::json_pointer(pointer));
}

bool SceneReader::has(const std::string& pointer, const char* key) const {
  return at(pointer).contains(key);
}

void SceneReader::object(const std::string& pointer,
                         std::initializer_list<const char*> keys) const {
  const json& v = at(pointer);
  if (!v.is_object())
    throw JsonFailure{pointer, "expected an object"};
  for (auto it = v.begin(); it != v.end(); ++it) {
    const bool known =
        std::any_of(keys.begin(), keys.end(), [&](const char* k) { return it.key() == k; });
    if (!known) {
      throw JsonFailure{json_pointer_child(pointer, it.key()),
                        "unknown key \"" + it.key() + "\" (expected " + list_names(keys) + ")"};
    }
  }
}

void SceneReader::require(const std::string& pointer, const char* key) const {
  if (!has(pointer, key)) {
    throw JsonFailure{pointer, std::string("missing key \"") + key + "\""};
  }
}

double SceneReader::raw_number(const std::string& pointer) const {
  const json& v = at(pointer);
  if (!v.is_number())
    throw JsonFailure{pointer, "expected a number"};
  return v.get<double>();
}

double SceneReader::number(const std::string& pointer) const {
  const double d = raw_number(pointer);
  if (std::abs(d) > kMaxCoordinate)
    throw JsonFailure{pointer, "number " + fmt(d) + " is beyond the limit of 1e15"};
  return d;
}

double SceneReader::in_range(const std::string& pointer, double lo, double hi, const char* range,
                             const std::string& what) const {
  const double d = raw_number(pointer);
  if (!(d >= lo && d <= hi)) {
    throw JsonFailure{
        pointer, (what.empty() ? "" : what + " ") + "must be in " + range + " (is " + fmt(d) + ")"};
  }
  return d;
}

glm::dvec3 SceneReader::vec3_in_range(const std::string& pointer, double lo, double hi,
                                      const char* range, const std::string& what) const {
  const json& v = at(pointer);
  if (v.is_number())
    return glm::dvec3(in_range(pointer, lo, hi, range, what));
  if (!v.is_array() || v.size() != 3)
    throw JsonFailure{pointer, "expected a number or [x, y, z]"};
  glm::dvec3 out;
  for (int i = 0; i < 3; ++i)
    out[i] = raw_number(json_pointer_child(pointer, size_t(i)));
  if (glm::any(glm::lessThan(out, glm::dvec3(lo))) ||
      glm::any(glm::greaterThan(out, glm::dvec3(hi)))) {
    throw JsonFailure{pointer, what + " must be in " + range + " (are " + fmt(out.x) + ", " +
                                   fmt(out.y) + ", " + fmt(out.z) + ")"};
  }
  return out;
}

double SceneReader::number(const std::string& pointer, const char* key, double fallback) const {
  return has(pointer, key) ? number(json_pointer_child(pointer, key)) : fallback;
}

double SceneReader::positive(const std::string& pointer, const char* key, double fallback) const {
  const double v = number(pointer, key, fallback);
  if (!(v > 0.0)) {
    throw JsonFailure{json_pointer_child(pointer, key), "must be positive (is " + fmt(v) + ")"};
  }
  return v;
}

int SceneReader::integer(const std::string& pointer, const char* key, int fallback, int lo,
                         int hi) const {
  if (!has(pointer, key))
    return fallback;
  const std::string p = json_pointer_child(pointer, key);
  const json& v = at(p);
  if (!v.is_number_integer())
    throw JsonFailure{p, "expected an integer"};
  const auto i = v.get<long long>();
  if (i < lo || i > hi) {
    throw JsonFailure{p, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                             "] (is " + std::to_string(i) + ")"};
  }
  return int(i);
}

std::string SceneReader::string(const std::string& pointer) const {
  const json& v = at(pointer);
  if (!v.is_string())
    throw JsonFailure{pointer, "expected a string"};
  return v.get<std::string>();
}

std::string SceneReader::string(const std::string& pointer, const char* key,
                                const std::string& fallback) const {
  return has(pointer, key) ? string(json_pointer_child(pointer, key)) : fallback;
}

glm::vec3 SceneReader::vec3(const std::string& pointer) const {
  const json& v = at(pointer);
  if (!v.is_array() || v.size() != 3)
    throw JsonFailure{pointer, "expected [x, y, z]"};
  glm::vec3 out;
  for (int i = 0; i < 3; ++i)
    out[i] = float(number(json_pointer_child(pointer, size_t(i))));
  return out;
}

glm::vec3 SceneReader::vec3(const std::string& pointer, const char* key, glm::vec3 fallback) const {
  return has(pointer, key) ? vec3(json_pointer_child(pointer, key)) : fallback;
}

glm::vec3 SceneReader::color(const std::string& pointer) const {
  return glm::vec3(vec3_in_range(pointer, 0.0, kMaxRadiometric, "[0, 1e6]", "colour components"));
}

glm::vec3 SceneReader::color(const std::string& pointer, const char* key,
                             glm::vec3 fallback) const {
  return has(pointer, key) ? color(json_pointer_child(pointer, key)) : fallback;
}

double SceneReader::intensity(const std::string& pointer) const {
  return has(pointer, "intensity")
             ? in_range(json_pointer_child(pointer, "intensity"), 0.0, kMaxRadiometric, "[0, 1e6]")
             : 1.0;
}

const json& SceneReader::array(const std::string& pointer, size_t max) const {
  const json& v = at(pointer);
  if (!v.is_array())
    throw JsonFailure{pointer, "expected an array"};
  if (v.size() > max) {
    throw JsonFailure{pointer, std::to_string(v.size()) + " elements, more than the limit of " +
                                   std::to_string(max)};
  }
  return v;
}

std::string SceneReader::file(const std::string& pointer) const {
  const std::string name = string(pointer);
  if (name.empty())
    throw JsonFailure{pointer, "empty file name"};
  std::string path, problem;
  if (!resolve_named_path(base_, name, files_root_, outside_, path, problem, true))
    throw JsonFailure{pointer, problem};
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw JsonFailure{pointer, "file not found: " + path};
  }
  return path;
}

std::string SceneReader::fmt(double v) {
  return double_text(v);
}

}  // namespace gfield
