// NAME.gimage.obj: the parameterised mesh (v), its geometry-image uvs (vt) and f v/vt triangles.

#include "geometry/parameterized_mesh.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string_view>
#include <unordered_map>

#include "geometry/text_scan.hpp"
#include "gfield/atomic_file.hpp"
#include "gfield/build_id.hpp"
#include "gfield/file_read.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {
/// The line that promises what the file holds, "#gfield-counts V T F" (v, vt and f lines; an
/// OBJ comment to other readers), so that a file cut short at a line end is an error too.
constexpr const char* kCountsTag = "#gfield-counts";
/// Corner uvs lie in [0,1]^2 but for the corners of triangles that cross the border of an
/// orbifold chart's square (their centroid is inside): never further out than this.
constexpr double kMinUv = -1.0;
constexpr double kMaxUv = 2.0;
}  // namespace

std::string parameterized_mesh_path(const std::string& geometry_image_path) {
  const std::string suffix = ".exr";
  std::string base = geometry_image_path;
  if (base.size() >= suffix.size()) {
    std::string tail = base.substr(base.size() - suffix.size());
    for (char& c : tail)
      c = char(std::tolower(static_cast<unsigned char>(c)));
    if (tail == suffix)
      base.resize(base.size() - suffix.size());
  }
  return base + ".obj";
}

bool save_parameterized_mesh(const std::string& filename, const ParameterizedMesh& pm,
                             std::string& error) {
  if (pm.corner_uv.size() != 3 * pm.mesh.triangles.size()) {
    error = filename + ": corner uv count does not match the triangles";
    return false;
  }
  // One vt per distinct uv value (corners that share a uv share a vt line).
  std::unordered_map<uint64_t, int> uv_index;
  std::vector<int> corner_vt(pm.corner_uv.size());
  std::vector<glm::vec2> vts;
  for (size_t c = 0; c < pm.corner_uv.size(); ++c) {
    uint32_t bits[2];
    std::memcpy(bits, &pm.corner_uv[c], sizeof(bits));
    const uint64_t key = (uint64_t(bits[0]) << 32) | bits[1];
    auto [it, inserted] = uv_index.emplace(key, int(vts.size()));
    if (inserted)
      vts.push_back(pm.corner_uv[c]);
    corner_vt[c] = it->second;
  }

  TemporaryFile temporary(filename);
  FILE* file = std::fopen(temporary.path().c_str(), "wb");
  if (!file) {
    error = filename + ": cannot write (" + std::strerror(errno) + ")";
    return false;
  }
  std::fprintf(file, "# gfield parameterised mesh: v = mesh coordinates, vt = geometry-image uv\n");
  std::fprintf(file, "%s %zu %zu %zu\n", kCountsTag, pm.mesh.positions.size(), vts.size(),
               pm.mesh.triangles.size());
  if (!pm.build_id.empty())
    std::fprintf(file, "# %s %s\n", kBuildIdAttribute, pm.build_id.c_str());
  for (const glm::dvec3& p : pm.mesh.positions)
    std::fprintf(file, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
  for (const glm::vec2& t : vts)
    std::fprintf(file, "vt %.9g %.9g\n", t.x, t.y);
  for (size_t f = 0; f < pm.mesh.triangles.size(); ++f) {
    const glm::ivec3& t = pm.mesh.triangles[f];
    std::fprintf(file, "f %d/%d %d/%d %d/%d\n", t[0] + 1, corner_vt[3 * f] + 1, t[1] + 1,
                 corner_vt[3 * f + 1] + 1, t[2] + 1, corner_vt[3 * f + 2] + 1);
  }
  errno = 0;
  const bool ok = std::fflush(file) == 0 && std::ferror(file) == 0;
  const int reason = errno;
  if (std::fclose(file) != 0 || !ok) {
    error = filename + ": cannot write (" + std::strerror(reason != 0 ? reason : errno) + ")";
    return false;
  }
  return temporary.commit(error);
}

namespace {

/// The id of a `# gfield.buildId ID` comment line; false for any other line.
bool parse_build_id_line(const std::string& line, std::string& build_id) {
  const std::string prefix = std::string("# ") + kBuildIdAttribute + " ";
  if (line.rfind(prefix, 0) != 0)
    return false;
  build_id = line.substr(prefix.size());
  if (!build_id.empty() && build_id.back() == '\r')
    build_id.pop_back();
  return true;
}

/// What a file holds, counted while reading, and the counts its header line promises.
struct Counts {
  std::int64_t vertices = 0, uvs = 0, triangles = 0;
};

bool read_counts(text::Words& words, Counts& counts, std::string& what) {
  std::string_view v, t, f;
  if (!words.next(v) || !words.next(t) || !words.next(f) ||
      !text::parse_int64(v, counts.vertices) || !text::parse_int64(t, counts.uvs) ||
      !text::parse_int64(f, counts.triangles) || !words.empty()) {
    what = "malformed counts line (expected \"" + std::string(kCountsTag) +
           " VERTICES UVS TRIANGLES\")";
    return false;
  }
  return true;
}

bool read_numbers(text::Words& words, double* values, int count, std::string& what) {
  std::string_view word;
  for (int k = 0; k < count; ++k) {
    if (!words.next(word) || !text::parse_double(word, values[k]) || !std::isfinite(values[k])) {
      what = word.empty() ? "expected " + std::to_string(count) + " numbers"
                          : text::quoted(word) + " is not a finite number";
      return false;
    }
  }
  if (words.next(word)) {
    what = "unexpected " + text::quoted(word) + " after " + std::to_string(count) + " numbers";
    return false;
  }
  return true;
}

/// A triangle "f v/vt v/vt v/vt" (a "/vn" after each is ignored): 0-based indices, each checked
/// against the 64-bit range [1, limit] before it is converted.
bool read_face(text::Words& words, glm::ivec3& v, glm::ivec3& t, std::string& what) {
  std::string_view word;
  for (int c = 0; c < 3; ++c) {
    std::int64_t a = 0, b = 0;
    const bool got = words.next(word);
    const size_t slash = word.find('/');
    const size_t second = word.find('/', slash == std::string_view::npos ? word.size() : slash + 1);
    const bool ok = got && slash != std::string_view::npos &&
                    text::parse_int64(word.substr(0, slash), a) &&
                    text::parse_int64(word.substr(slash + 1, second - slash - 1), b);
    if (!ok) {
      what = "faces must be triangles written as v/vt (found " + text::quoted(word) + ")";
      return false;
    }
    if (a < 1 || a > kMaxMeshVertices || b < 1 || b > kMaxMeshVertices) {
      what =
          "face index " + std::to_string(a < 1 || a > kMaxMeshVertices ? a : b) + " out of range";
      return false;
    }
    v[c] = int(a - 1);
    t[c] = int(b - 1);
  }
  if (words.next(word)) {
    what = "faces must be triangles written as v/vt (a fourth corner " + text::quoted(word) + ")";
    return false;
  }
  return true;
}

/// One statement; `vts` and `vt_triangles` collect the uvs and each triangle's uv indices.
bool read_line(std::string_view line, ParameterizedMesh& pm, std::vector<glm::vec2>& vts,
               std::vector<glm::ivec3>& vt_triangles, Counts& promised, std::string& what) {
  text::Words words(line);
  std::string_view first;
  words.next(first);
  double values[3];
  if (first == "v") {
    if (!read_numbers(words, values, 3, what)) {
      return false;
    }
    if (std::abs(values[0]) > kMaxAssetCoordinate || std::abs(values[1]) > kMaxAssetCoordinate ||
        std::abs(values[2]) > kMaxAssetCoordinate) {
      what = "vertex coordinate beyond the limit of 1e16";
      return false;
    }
    pm.mesh.positions.emplace_back(values[0], values[1], values[2]);
  } else if (first == "vt") {
    if (!read_numbers(words, values, 2, what)) {
      return false;
    }
    if (values[0] < kMinUv || values[0] > kMaxUv || values[1] < kMinUv || values[1] > kMaxUv) {
      what = "uv (" + std::to_string(values[0]) + ", " + std::to_string(values[1]) +
             ") outside [-1, 2]^2";
      return false;
    }
    vts.emplace_back(float(values[0]), float(values[1]));
  } else if (first == "f") {
    glm::ivec3 v, t;
    if (!read_face(words, v, t, what)) {
      return false;
    }
    pm.mesh.triangles.push_back(v);
    vt_triangles.push_back(t);
  } else if (first == kCountsTag) {
    return read_counts(words, promised, what);
  } else if (first == "#") {
    std::string_view key, id;
    if (words.next(key) && key == kBuildIdAttribute && words.next(id))
      pm.build_id = std::string(id);
  }
  return true;
}

}  // namespace

bool load_parameterized_mesh(const std::string& filename, ParameterizedMesh& pm,
                             std::string& error) {
  std::string data;
  if (!read_file(filename, kMaxMeshFileBytes, data, error)) {
    return false;
  }
  ParameterizedMesh out;
  std::vector<glm::vec2> vts;
  std::vector<glm::ivec3> vt_triangles;
  Counts promised{-1, -1, -1};
  text::Lines lines(data);
  std::string_view line;
  std::string what;
  while (lines.next(line)) {
    if (!read_line(line, out, vts, vt_triangles, promised, what)) {
      error = filename + ":" + std::to_string(lines.number()) + ": " + what;
      return false;
    }
  }
  const Counts found{std::int64_t(out.mesh.positions.size()), std::int64_t(vts.size()),
                     std::int64_t(out.mesh.triangles.size())};
  if (!lines.line_ended() && !data.empty()) {
    error = filename + ": truncated (the last line has no end)";
    return false;
  }
  if (promised.vertices >= 0 && (promised.vertices != found.vertices || promised.uvs != found.uvs ||
                                 promised.triangles != found.triangles)) {
    error = filename + ": truncated or corrupt: " + std::to_string(found.vertices) + " v, " +
            std::to_string(found.uvs) + " vt, " + std::to_string(found.triangles) +
            " f, but the counts line says " + std::to_string(promised.vertices) + ", " +
            std::to_string(promised.uvs) + ", " + std::to_string(promised.triangles);
    return false;
  }
  if (out.mesh.triangles.empty()) {
    error = filename + ": no faces";
    return false;
  }
  out.corner_uv.resize(3 * out.mesh.triangles.size());
  for (size_t f = 0; f < out.mesh.triangles.size(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int v = out.mesh.triangles[f][c];
      const int t = vt_triangles[f][c];
      if (size_t(v) >= out.mesh.positions.size() || size_t(t) >= vts.size()) {
        error = filename + ": face " + std::to_string(f) + " has an index out of range (" +
                std::to_string(found.vertices) + " v, " + std::to_string(found.uvs) + " vt)";
        return false;
      }
      out.corner_uv[3 * f + size_t(c)] = vts[size_t(t)];
    }
  }
  pm = std::move(out);
  return true;
}

bool mesh_inside_box(const ParameterizedMesh& pm, const Box& box) {
  for (const glm::dvec3& p : pm.mesh.positions) {
    const glm::vec3 q(p);
    if (glm::any(glm::lessThan(q, box.min)) || glm::any(glm::greaterThan(q, box.max))) {
      return false;
    }
  }
  return true;
}

bool read_parameterized_mesh_build_id(const std::string& filename, std::string& build_id,
                                      std::string& error) {
  std::ifstream in(filename);
  if (!in) {
    error = filename + ": cannot open";
    return false;
  }
  build_id.clear();
  std::string line;
  while (std::getline(in, line) && line.rfind('#', 0) == 0) {
    if (parse_build_id_line(line, build_id))
      break;
  }
  return true;
}

bool load_parameterized_mesh_of(const GeometryImage& image, const std::string& image_file,
                                ParameterizedMesh& pm, std::string& error) {
  const std::string filename = parameterized_mesh_path(image_file);
  return load_parameterized_mesh(filename, pm, error) &&
         check_same_build(filename, pm.build_id, image_file, image.build_id, error);
}

}  // namespace gfield
