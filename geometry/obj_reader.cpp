// Wavefront OBJ: `v x y z [w | r g b]` vertices and `f` faces whose corners are `v`, `v/vt`,
// `v//vn` or `v/vt/vn` (1-based; negative indices count back from the last vertex read). Other
// statements (vt, vn, g, o, s, usemtl, mtllib, l, p, ...) are skipped.

#include <vector>

#include "geometry/mesh_readers.hpp"
#include "geometry/text_scan.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// Vertex statements in the file: faces may name vertices defined after them.
std::int64_t count_vertices(std::string_view data) {
  text::Lines lines(data);
  std::string_view line;
  std::int64_t count = 0;
  while (lines.next(line)) {
    text::Words words(line);
    std::string_view first;
    count += words.next(first) && first == "v" ? 1 : 0;
  }
  return count;
}

bool read_vertex(text::Words& words, MeshSoup& soup, std::string& what) {
  double xyz[3];
  std::string_view word;
  for (double& v : xyz) {
    if (!words.next(word)) {
      what = "a vertex needs 3 coordinates";
      return false;
    }
    if (!text::parse_double(word, v)) {
      what = "vertex coordinate " + text::quoted(word) + " is not a number";
      return false;
    }
  }
  for (int extra = 0; words.next(word); ++extra) {  // w, or a colour r g b
    double ignored = 0.0;
    if (extra == 4 || !text::parse_double(word, ignored)) {
      what = "unexpected " + text::quoted(word) + " after a vertex's coordinates";
      return false;
    }
  }
  return add_vertex(soup, xyz[0], xyz[1], xyz[2], what);
}

/// The optional "vt", "vt/vn" or "/vn" after a corner's first slash: integers or empty.
bool optional_indices(std::string_view rest) {
  const size_t slash = rest.find('/');
  const std::string_view vt = rest.substr(0, slash);
  const std::string_view vn = slash == std::string_view::npos ? "" : rest.substr(slash + 1);
  std::int64_t ignored = 0;
  return (vt.empty() || text::parse_int64(vt, ignored)) &&
         (vn.empty() || text::parse_int64(vn, ignored));
}

/// One corner "v[/vt[/vn]]": the resolved 0-based vertex index.
bool read_corner(std::string_view word, std::int64_t vertices_so_far, std::int64_t vertices,
                 std::int64_t& index, std::string& what) {
  const size_t slash = word.find('/');
  std::int64_t value = 0;
  const bool ok = text::parse_int64(word.substr(0, slash), value) && value != 0 &&
                  (slash == std::string_view::npos || optional_indices(word.substr(slash + 1)));
  if (!ok) {
    what = "malformed face corner " + text::quoted(word);
    return false;
  }
  if (value < -vertices_so_far || value > vertices) {
    what = "face index " + std::to_string(value) + " out of range (" + std::to_string(vertices) +
           " vertices)";
    return false;
  }
  index = value > 0 ? value - 1 : vertices_so_far + value;
  return true;
}

}  // namespace

bool read_obj(std::string_view data, MeshSoup& soup, ReadFailure& failure) {
  const std::int64_t vertices = count_vertices(data);
  if (vertices > kMaxMeshVertices) {
    failure.what =
        std::to_string(vertices) + " vertices (at most " + std::to_string(kMaxMeshVertices) + ")";
    return false;
  }
  soup.mesh.positions.reserve(size_t(vertices));
  text::Lines lines(data);
  std::string_view line;
  std::vector<std::int64_t> corners;
  while (lines.next(line)) {
    failure.line = lines.number();
    text::Words words(line);
    std::string_view first;
    if (!words.next(first)) {
      continue;
    }
    if (first == "v") {
      if (!read_vertex(words, soup, failure.what)) {
        return false;
      }
    } else if (first == "f") {
      corners.clear();
      std::string_view word;
      while (words.next(word)) {
        std::int64_t index = 0;
        if (!read_corner(word, std::int64_t(soup.mesh.positions.size()), vertices, index,
                         failure.what)) {
          return false;
        }
        corners.push_back(index);
      }
      if (!add_polygon(soup, corners, failure.what)) {
        return false;
      }
    }
  }
  failure.line = 0;
  return true;
}

}  // namespace gfield
