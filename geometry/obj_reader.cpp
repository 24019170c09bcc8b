// Wavefront OBJ: `v x y z [w | r g b]` vertices (r g b: an sRGB vertex colour in [0, 1]), `vt u
// v [w]` texture coordinates, `f` faces whose corners are `v`, `v/vt`, `v//vn` or `v/vt/vn`
// (1-based; negative indices count back from the last vertex or texture coordinate read),
// `usemtl NAME` (the material of the faces that follow) and `mtllib FILE...` (material
// libraries, read by mtl_reader.cpp). Other statements (vn, g, o, s, l, p, ...) are skipped.

#include <map>
#include <vector>

#include "geometry/mesh_readers.hpp"
#include "geometry/text_scan.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// Vertex and texture-coordinate statements in the file: faces may name ones defined after them.
struct ObjCounts {
  std::int64_t vertices = 0;
  std::int64_t uvs = 0;
};

ObjCounts count_statements(std::string_view data) {
  text::Lines lines(data);
  std::string_view line;
  ObjCounts counts;
  while (lines.next(line)) {
    text::Words words(line);
    std::string_view first;
    if (words.next(first)) {
      counts.vertices += first == "v" ? 1 : 0;
      counts.uvs += first == "vt" ? 1 : 0;
    }
  }
  return counts;
}

/// Reads `count` numbers (at least `required`); false with `what` for a word that is not one.
bool read_numbers(text::Words& words, int required, int count, double* values, int& read,
                  const char* what_for, std::string& what) {
  std::string_view word;
  for (read = 0; read < count && words.next(word); ++read) {
    if (!text::parse_double(word, values[read])) {
      what = std::string(what_for) + " " + text::quoted(word) + " is not a number";
      return false;
    }
  }
  if (read < required) {
    what = std::string("a ") + what_for + " needs " + std::to_string(required) + " numbers";
    return false;
  }
  if (words.next(word)) {
    what = "unexpected " + text::quoted(word) + " after a " + what_for;
    return false;
  }
  return true;
}

bool read_vertex(text::Words& words, MeshSoup& soup, std::string& what) {
  double v[7];
  int read = 0;
  if (!read_numbers(words, 3, 7, v, read, "vertex coordinate", what) ||
      !add_vertex(soup, v[0], v[1], v[2], what)) {
    return false;
  }
  if (read < 6) {
    return true;  // x y z [w]
  }
  // Colours in [0, 1] are sRGB (as MeshLab writes them); one with a component above 1 is linear
  // (HDR), all three components alike.
  glm::dvec3 color(v[3], v[4], v[5]);
  if (glm::all(glm::greaterThanEqual(color, glm::dvec3(0.0))) &&
      glm::all(glm::lessThanEqual(color, glm::dvec3(1.0)))) {
    for (int k = 0; k < 3; ++k) {
      color[k] = srgb_to_linear(float(color[k]));
    }
  }
  return set_vertex_color(soup, color, what);
}

bool read_uv(text::Words& words, MeshSoup& soup, std::string& what) {
  double v[3];
  int read = 0;
  return read_numbers(words, 1, 3, v, read, "texture coordinate", what) &&
         add_uv(soup, v[0], read > 1 ? v[1] : 0.0, what);
}

/// A 1-based (or negative, relative) index `value` of `so_far` statements read and `total` in
/// the file, made 0-based; false with `what` when out of range.
bool resolve(std::int64_t value, std::int64_t so_far, std::int64_t total, const char* what_for,
             std::int64_t& index, std::string& what) {
  if (value == 0 || value < -so_far || value > total) {
    what = std::string(what_for) + " index " + std::to_string(value) + " out of range (" +
           std::to_string(total) + " in the file)";
    return false;
  }
  index = value > 0 ? value - 1 : so_far + value;
  return true;
}

/// One corner "v[/vt[/vn]]": the resolved 0-based vertex index and texture-coordinate index
/// (-1: none).
bool read_corner(std::string_view word, const MeshSoup& soup, const ObjCounts& counts,
                 std::int64_t& index, std::int64_t& uv, std::string& what) {
  const size_t slash = word.find('/');
  const std::string_view rest = slash == std::string_view::npos ? "" : word.substr(slash + 1);
  const size_t second = rest.find('/');
  const std::string_view vt = rest.substr(0, second);
  const std::string_view vn = second == std::string_view::npos ? "" : rest.substr(second + 1);
  std::int64_t value = 0, uv_value = 0, ignored = 0;
  const bool ok = text::parse_int64(word.substr(0, slash), value) &&
                  (vt.empty() || text::parse_int64(vt, uv_value)) &&
                  (vn.empty() || text::parse_int64(vn, ignored));
  if (!ok) {
    what = "malformed face corner " + text::quoted(word);
    return false;
  }
  uv = -1;
  return resolve(value, std::int64_t(soup.mesh.positions.size()), counts.vertices, "face", index,
                 what) &&
         (vt.empty() || resolve(uv_value, std::int64_t(soup.uvs.size()), counts.uvs,
                                "texture coordinate", uv, what));
}

bool read_face(text::Words& words, MeshSoup& soup, const ObjCounts& counts, int material,
               std::string& what) {
  std::vector<std::int64_t> corners, uvs;
  std::string_view word;
  while (words.next(word)) {
    std::int64_t index = 0, uv = -1;
    if (!read_corner(word, soup, counts, index, uv, what)) {
      return false;
    }
    corners.push_back(index);
    if (uv >= 0) {
      uvs.push_back(uv);
    }
  }
  // A face's corners all have texture coordinates, or it has none.
  const bool textured = uvs.size() == corners.size();
  if (!uvs.empty() && !textured) {
    what = "a face with texture coordinates at some corners only";
    return false;
  }
  return add_polygon(soup, corners, what, {std::span<const std::int64_t>(uvs), material});
}

/// `usemtl NAME`: the index of material NAME (made on first use).
bool use_material(text::Words& words, std::string_view line, MeshSoup& soup,
                  std::map<std::string, int, std::less<>>& names, int& material,
                  std::string& what) {
  std::string_view name;
  if (!words.next(name)) {
    what = "usemtl without a material name";
    return false;
  }
  // The name is the rest of the line (names may hold spaces).
  name = line.substr(size_t(name.data() - line.data()));
  while (!name.empty() && text::is_space(name.back())) {
    name.remove_suffix(1);
  }
  const auto found = names.find(name);
  if (found != names.end()) {
    material = found->second;
    return true;
  }
  if (soup.materials.size() >= kMaxMeshMaterials) {
    what = "more than " + std::to_string(kMaxMeshMaterials) + " materials";
    return false;
  }
  material = int(soup.materials.size());
  soup.materials.push_back({std::string(name), glm::vec3(1.0f), -1});
  names.emplace(std::string(name), material);
  return true;
}

}  // namespace

bool read_obj(std::string_view data, MeshSoup& soup, ReadFailure& failure) {
  const ObjCounts counts = count_statements(data);
  if (counts.vertices > kMaxMeshVertices || counts.uvs > kMaxMeshVertices) {
    failure.what = std::to_string(counts.vertices) + " vertices and " + std::to_string(counts.uvs) +
                   " texture coordinates (at most " + std::to_string(kMaxMeshVertices) + " each)";
    return false;
  }
  soup.mesh.positions.reserve(size_t(counts.vertices));
  soup.uvs.reserve(size_t(counts.uvs));
  std::map<std::string, int, std::less<>> material_names;
  int material = -1;
  text::Lines lines(data);
  std::string_view line;
  while (lines.next(line)) {
    failure.line = lines.number();
    text::Words words(line);
    std::string_view first, word;
    if (!words.next(first)) {
      continue;
    }
    bool ok = true;
    if (first == "v") {
      ok = read_vertex(words, soup, failure.what);
    } else if (first == "vt") {
      ok = read_uv(words, soup, failure.what);
    } else if (first == "f") {
      ok = read_face(words, soup, counts, material, failure.what);
    } else if (first == "usemtl") {
      ok = use_material(words, line, soup, material_names, material, failure.what);
    } else if (first == "mtllib") {
      while (ok && words.next(word)) {
        ok = soup.libraries.size() < kMaxMeshMaterials;
        if (ok) {
          soup.libraries.emplace_back(word);
        } else {
          failure.what = "more than " + std::to_string(kMaxMeshMaterials) + " material libraries";
        }
      }
    }
    if (!ok) {
      return false;
    }
  }
  if (!soup.vertex_color.empty()) {
    soup.vertex_color.resize(soup.mesh.positions.size(), glm::vec3(1.0f));
  }
  failure.line = 0;
  return true;
}

}  // namespace gfield
