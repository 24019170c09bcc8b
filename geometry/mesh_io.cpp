#include "geometry/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "geometry/mesh_readers.hpp"
#include "gfield/atomic_file.hpp"
#include "gfield/file_read.hpp"
#include "gfield/limits.hpp"

namespace gfield {

namespace {

std::string lower_extension(const std::string& filename) {
  std::string ext = std::filesystem::path(filename).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

bool load_mesh(const std::string& filename, TriangleMesh& mesh, std::string& error,
               MeshLoadStats* stats) {
  const std::string ext = lower_extension(filename);
  using Reader = bool (*)(std::string_view, MeshSoup&, ReadFailure&);
  const Reader reader = ext == ".obj"   ? read_obj
                        : ext == ".ply" ? read_ply
                        : ext == ".off" ? read_off
                        : ext == ".stl" ? read_stl
                                        : nullptr;
  if (reader == nullptr) {
    error = filename + ": unknown mesh extension '" + ext + "' (expected .obj, .ply, .off, .stl)";
    return false;
  }
  std::string data;
  if (!read_file(filename, kMaxMeshFileBytes, data, error)) {
    return false;
  }
  MeshSoup soup;
  ReadFailure failure;
  if (!reader(data, soup, failure)) {
    error = filename;
    if (failure.line > 0) {
      error += ':' + std::to_string(failure.line);
    }
    error += ": " + failure.what;
    return false;
  }
  if (soup.mesh.triangles.empty()) {
    error = filename + ": no faces (" + std::to_string(soup.mesh.positions.size()) +
            " vertices read; triangle strips and point clouds are not supported)";
    return false;
  }
  mesh = std::move(soup.mesh);
  if (stats) {
    *stats = soup.stats;
  }
  return true;
}

bool save_obj(const std::string& filename, const TriangleMesh& mesh, std::string& error) {
  std::ostringstream out;
  out.precision(9);
  for (const glm::dvec3& p : mesh.positions) {
    out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  }
  for (const glm::ivec3& t : mesh.triangles) {
    out << "f " << t.x + 1 << ' ' << t.y + 1 << ' ' << t.z + 1 << '\n';
  }
  return write_text_file(filename, out.str(), error);
}

}  // namespace gfield
