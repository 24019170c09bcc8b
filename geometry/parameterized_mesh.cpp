// NAME.gimage.obj: the parameterised mesh (v), its geometry-image uvs (vt) and f v/vt triangles.

#include "geometry/parameterized_mesh.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string_view>
#include <unordered_map>

#include "gfield/atomic_file.hpp"
#include "gfield/build_id.hpp"

namespace gfield {

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
    error = filename + ": cannot write";
    return false;
  }
  std::fprintf(file, "# gfield parameterised mesh: v = mesh coordinates, vt = geometry-image uv\n");
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
  const bool ok = std::ferror(file) == 0;
  if (std::fclose(file) != 0 || !ok) {
    error = filename + ": write failed";
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

/// Parses "a/b[/c]" into one-based (a, b); false if either is missing or not an integer.
bool parse_corner(std::string_view token, long& v, long& vt) {
  const size_t slash = token.find('/');
  if (slash == std::string_view::npos)
    return false;
  const std::string_view a = token.substr(0, slash);
  std::string_view b = token.substr(slash + 1);
  b = b.substr(0, b.find('/'));
  return std::from_chars(a.data(), a.data() + a.size(), v).ec == std::errc() &&
         std::from_chars(b.data(), b.data() + b.size(), vt).ec == std::errc();
}

}  // namespace

bool load_parameterized_mesh(const std::string& filename, ParameterizedMesh& pm,
                             std::string& error) {
  std::ifstream in(filename);
  if (!in) {
    error = filename + ": cannot open";
    return false;
  }
  pm = {};
  std::vector<glm::vec2> vts;
  std::vector<glm::ivec3> vt_triangles;
  std::string line;
  size_t line_number = 0;
  auto fail = [&](const std::string& what) {
    error = filename + ":" + std::to_string(line_number) + ": " + what;
    return false;
  };
  while (std::getline(in, line)) {
    ++line_number;
    if (parse_build_id_line(line, pm.build_id))
      continue;
    if (line.rfind("v ", 0) == 0) {
      glm::dvec3 p;
      if (std::sscanf(line.c_str() + 2, "%lf %lf %lf", &p.x, &p.y, &p.z) != 3)
        return fail("bad vertex");
      pm.mesh.positions.push_back(p);
    } else if (line.rfind("vt ", 0) == 0) {
      glm::vec2 t;
      if (std::sscanf(line.c_str() + 3, "%f %f", &t.x, &t.y) != 2)
        return fail("bad uv");
      vts.push_back(t);
    } else if (line.rfind("f ", 0) == 0) {
      std::string_view rest(line);
      rest.remove_prefix(2);
      glm::ivec3 v, t;
      int corners = 0;
      while (!rest.empty()) {
        const size_t start = rest.find_first_not_of(" \t\r");
        if (start == std::string_view::npos)
          break;
        rest.remove_prefix(start);
        const size_t end = rest.find_first_of(" \t\r");
        const std::string_view token = rest.substr(0, end);
        rest.remove_prefix(end == std::string_view::npos ? rest.size() : end);
        long a = 0, b = 0;
        if (corners == 3 || !parse_corner(token, a, b))
          return fail("faces must be triangles written as v/vt");
        v[corners] = int(a - 1);
        t[corners] = int(b - 1);
        ++corners;
      }
      if (corners != 3)
        return fail("faces must be triangles written as v/vt");
      pm.mesh.triangles.push_back(v);
      vt_triangles.push_back(t);
    }
  }
  if (pm.mesh.triangles.empty()) {
    error = filename + ": no faces";
    return false;
  }
  pm.corner_uv.resize(3 * pm.mesh.triangles.size());
  for (size_t f = 0; f < pm.mesh.triangles.size(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int v = pm.mesh.triangles[f][c];
      const int t = vt_triangles[f][c];
      if (v < 0 || size_t(v) >= pm.mesh.positions.size() || t < 0 || size_t(t) >= vts.size()) {
        error = filename + ": face " + std::to_string(f) + " has an index out of range";
        return false;
      }
      pm.corner_uv[3 * f + c] = vts[t];
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
