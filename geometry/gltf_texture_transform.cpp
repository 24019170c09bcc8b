#include "geometry/gltf_texture_transform.hpp"

#include <cmath>

#include "gfield/limits.hpp"

namespace gfield {
namespace {

using nlohmann::json;

/// Two finite numbers within +-kMaxTextureCoordinate at `key` of `ext` (`value` when absent).
bool pair_member(const json& ext, const char* key, glm::dvec2& value, std::string& what) {
  if (!ext.contains(key))
    return true;
  const json& v = ext[key];
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() ||
      !(std::abs(v[0].get<double>()) <= kMaxTextureCoordinate) ||
      !(std::abs(v[1].get<double>()) <= kMaxTextureCoordinate)) {
    what = std::string("KHR_texture_transform.") + key +
           ": expected 2 numbers within +-1e4 (the limit of texture coordinates)";
    return false;
  }
  value = glm::dvec2(v[0].get<double>(), v[1].get<double>());
  return true;
}

/// A texCoord member: an integer in [0, 255].
bool tex_coord_member(const json& object, const char* where, int& value, std::string& what) {
  if (!object.contains("texCoord"))
    return true;
  const json& v = object["texCoord"];
  if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::int64_t>() > 255) {
    what = std::string(where) + "texCoord: expected an integer in [0, 255]";
    return false;
  }
  value = v.get<int>();
  return true;
}

}  // namespace

bool texture_transform(const json& info, TextureTransform& transform, std::string& what) {
  transform = TextureTransform{};
  if (!info.is_object() || !tex_coord_member(info, "", transform.tex_coord, what))
    return info.is_object();
  if (!info.contains("extensions") || !info["extensions"].is_object() ||
      !info["extensions"].contains("KHR_texture_transform"))
    return true;
  const json& ext = info["extensions"]["KHR_texture_transform"];
  glm::dvec2 offset(0.0), scale(1.0);
  double rotation = 0.0;
  if (!ext.is_object() || !pair_member(ext, "offset", offset, what) ||
      !pair_member(ext, "scale", scale, what) ||
      !tex_coord_member(ext, "KHR_texture_transform.", transform.tex_coord, what)) {
    what = what.empty() ? "KHR_texture_transform: expected an object" : what;
    return false;
  }
  if (ext.contains("rotation")) {
    if (!ext["rotation"].is_number() || !std::isfinite(ext["rotation"].get<double>())) {
      what = "KHR_texture_transform.rotation: expected a number (radians)";
      return false;
    }
    rotation = ext["rotation"].get<double>();
  }
  // The extension's matrices (column-major): translation * rotation * scale.
  const double c = std::cos(rotation), s = std::sin(rotation);
  const glm::dmat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
  const glm::dmat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
  const glm::dmat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
  transform.matrix = t * r * sc;
  transform.transformed = true;
  return true;
}

glm::dvec2 transformed_uv(const TextureTransform& transform, glm::dvec2 uv) {
  const glm::dvec3 t = transform.matrix * glm::dvec3(uv, 1.0);
  return glm::dvec2(t.x, 1.0 - t.y);
}

}  // namespace gfield
