#pragma once
// Reading the values of a scene file's JSON document (core/src/scene_json.cpp): each read checks
// its value (type, range, the keys an object may hold, a file's place) and throws JsonFailure with
// the value's JSON pointer, which parse_scene turns into "FILE:LINE:COL: path: message".

#include <filesystem>
#include <initializer_list>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "gfield/confined_path.hpp"
#include "gfield/located_json.hpp"

namespace gfield {

/// Colours, intensities and absorption coefficients: at most this (radiance stays far inside
/// float range through any number of bounces' products).
inline constexpr double kMaxRadiometric = 1e6;

/// "/objects/2/material" -> "objects[2].material".
std::string readable_path(const std::string& pointer);

/// "a, b or c".
std::string list_names(std::initializer_list<const char*> names);

/// Reads values out of the document by JSON pointer, throwing JsonFailure with the pointer.
class SceneReader {
 public:
  /// `base`: the scene file's folder; `files_root`: the folder its files must lie in
  /// (scene_root) unless `outside` is kAllowed.
  SceneReader(const nlohmann::json& root, std::filesystem::path base,
              std::filesystem::path files_root, OutsidePaths outside);

  const nlohmann::json& at(const std::string& pointer) const;
  bool has(const std::string& pointer, const char* key) const;

  /// Requires an object with only the given keys.
  void object(const std::string& pointer, std::initializer_list<const char*> keys) const;
  void require(const std::string& pointer, const char* key) const;

  /// A number, any finite value (the JSON parser refuses the others).
  double raw_number(const std::string& pointer) const;
  /// A number within +-kMaxCoordinate (every number of a scene without a range of its own).
  double number(const std::string& pointer) const;
  /// A number in [lo, hi] (`range`: the interval as the docs write it, e.g. "[0, 1e6]");
  /// `what` names it in the message ("must be in ..." when empty).
  double in_range(const std::string& pointer, double lo, double hi, const char* range,
                  const std::string& what = "") const;
  /// [x, y, z] or one number for all three, each in [lo, hi] (`range`, `what`: as in_range).
  glm::dvec3 vec3_in_range(const std::string& pointer, double lo, double hi, const char* range,
                           const std::string& what) const;
  /// The number at `key` of the object at `pointer`, or `fallback` when it has none.
  double number(const std::string& pointer, const char* key, double fallback) const;
  /// The same, and it must be positive.
  double positive(const std::string& pointer, const char* key, double fallback) const;
  /// An integer in [lo, hi] at `key`, or `fallback`.
  int integer(const std::string& pointer, const char* key, int fallback, int lo, int hi) const;
  std::string string(const std::string& pointer) const;
  std::string string(const std::string& pointer, const char* key,
                     const std::string& fallback) const;
  /// [x, y, z], each a number().
  glm::vec3 vec3(const std::string& pointer) const;
  glm::vec3 vec3(const std::string& pointer, const char* key, glm::vec3 fallback) const;
  /// A colour: [r, g, b] or one number for grey; components in [0, kMaxRadiometric].
  glm::vec3 color(const std::string& pointer) const;
  glm::vec3 color(const std::string& pointer, const char* key, glm::vec3 fallback) const;
  /// An intensity in [0, kMaxRadiometric] (default 1).
  double intensity(const std::string& pointer) const;
  /// An array of at most `max` elements.
  const nlohmann::json& array(const std::string& pointer, size_t max) const;
  /// A file path relative to the scene file, inside the scene's root unless outside paths are
  /// allowed (confined_path.hpp); must exist.
  std::string file(const std::string& pointer) const;
  OutsidePaths outside() const { return outside_; }

  /// The shortest text of `v` that reads back exactly (a value just past a bound shows it).
  static std::string fmt(double v);

 private:
  const nlohmann::json& root_;
  std::filesystem::path base_;
  std::filesystem::path files_root_;
  OutsidePaths outside_;
};

}  // namespace gfield
