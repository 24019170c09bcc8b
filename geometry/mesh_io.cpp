#include "geometry/mesh_io.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <glm/gtx/compatibility.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "gfield/atomic_file.hpp"

namespace gfield {

namespace {

using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;
using OpenMesh::IO::BaseImporter;

// Collects what OpenMesh's readers parse into a polygon soup, without building a half-edge
// structure (which would silently drop non-manifold faces and hide them from the topology
// report). Out-of-range indices are recorded instead of followed.
class SoupImporter final : public BaseImporter {
 public:
  std::vector<glm::dvec3> positions;
  std::vector<glm::ivec3> triangles;
  size_t polygons = 0;
  size_t triangulated = 0;
  size_t bad_indices = 0;
  size_t short_faces = 0;

  VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    return add_vertex(OpenMesh::Vec3d(p[0], p[1], p[2]));
  }
  VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    positions.emplace_back(p[0], p[1], p[2]);
    return VertexHandle(int(positions.size()) - 1);
  }
  VertexHandle add_vertex() override { return add_vertex(OpenMesh::Vec3d(0.0, 0.0, 0.0)); }
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }

  FaceHandle add_face(const VHandles& corners) override {
    ++polygons;
    if (corners.size() < 3) {
      ++short_faces;
      return FaceHandle();
    }
    for (const VertexHandle& v : corners) {
      if (v.idx() < 0 || size_t(v.idx()) >= positions.size()) {
        ++bad_indices;
        return FaceHandle();
      }
    }
    if (corners.size() > 3) {
      ++triangulated;
    }
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
      triangles.emplace_back(corners[0].idx(), corners[k].idx(), corners[k + 1].idx());
    }
    return FaceHandle(int(polygons) - 1);
  }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }

  // Attributes the project does not use.
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_point(VertexHandle v, const OpenMesh::Vec3f& p) override {
    if (v.idx() >= 0 && size_t(v.idx()) < positions.size()) {
      positions[size_t(v.idx())] = glm::dvec3(p[0], p[1], p[2]);
    }
  }
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_normal(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

  size_t n_vertices() const override { return positions.size(); }
  size_t n_faces() const override { return polygons; }
  size_t n_edges() const override { return 0; }
};

std::string lower_extension(const std::string& filename) {
  std::string ext = std::filesystem::path(filename).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// OpenMesh's OBJ reader skips face indices beyond the vertex count (with a message on
// std::cerr) instead of failing: find them ourselves so that a corrupt file is an error.
bool find_obj_index_error(const std::string& filename, size_t vertex_count, std::string& error) {
  std::ifstream in(filename);
  std::string line;
  size_t line_number = 0;
  size_t vertices_so_far = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.size() < 2) {
      continue;
    }
    if (line[0] == 'v' && std::isspace(static_cast<unsigned char>(line[1]))) {
      ++vertices_so_far;
      continue;
    }
    if (line[0] != 'f' || !std::isspace(static_cast<unsigned char>(line[1]))) {
      continue;
    }
    std::istringstream corners(line.substr(2));
    std::string corner;
    while (corners >> corner) {
      long index = 0;
      try {
        index = std::stol(corner.substr(0, corner.find('/')));
      } catch (const std::exception&) {
        error = filename + ":" + std::to_string(line_number) + ": malformed face corner '" +
                corner + "'";
        return true;
      }
      // OBJ indices are 1-based; negative ones count back from the last vertex read.
      const long resolved = index > 0 ? index - 1 : long(vertices_so_far) + index;
      if (index == 0 || resolved < 0 || size_t(resolved) >= vertex_count) {
        error = filename + ":" + std::to_string(line_number) + ": face index " +
                std::to_string(index) + " out of range (" + std::to_string(vertex_count) +
                " vertices)";
        return true;
      }
    }
  }
  return false;
}

// OpenMesh's text readers skip or zero a coordinate they cannot parse ("nan", "inf", 1e39 in a
// float) instead of failing. Scan the vertex lines of text OBJ, OFF and STL files ourselves.
bool find_text_coordinate_error(const std::string& filename, const std::string& ext,
                                std::string& error) {
  std::ifstream in(filename, std::ios::binary);
  std::string line;
  size_t line_number = 0;
  long off_vertices_left = -1;  // OFF: vertex lines still to come after the counts line
  bool off_counts_seen = false;
  while (std::getline(in, line)) {
    ++line_number;
    std::istringstream words(line);
    std::string first;
    if (!(words >> first) || first[0] == '#') {
      continue;
    }
    bool vertex_line = false;
    if (ext == ".obj") {
      vertex_line = first == "v";
    } else if (ext == ".stl") {
      if (line_number == 1 && first != "solid") {
        return false;  // binary STL: floats are read as stored and checked after loading
      }
      vertex_line = first == "vertex";
    } else if (ext == ".off") {
      if (line_number == 1 && first.find("OFF") != std::string::npos) {
        if (first.find("BINARY") != std::string::npos || line.find("BINARY") != std::string::npos) {
          return false;
        }
        continue;
      }
      if (!off_counts_seen) {
        off_counts_seen = true;
        off_vertices_left = std::atol(first.c_str());
        continue;
      }
      if (off_vertices_left <= 0) {
        return false;
      }
      --off_vertices_left;
      words.seekg(0);
      vertex_line = true;
    }
    if (!vertex_line) {
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      std::string token;
      words >> token;
      char* end = nullptr;
      const float value = std::strtof(token.c_str(), &end);
      if (token.empty() || end != token.c_str() + token.size() || !std::isfinite(value)) {
        error = filename + ":" + std::to_string(line_number) + ": vertex coordinate '" + token +
                "' is not a finite float (NaN or infinite coordinates are not allowed)";
        return true;
      }
    }
  }
  return false;
}

// Silences OpenMesh's chatter on std::cerr/std::clog while a reader runs; our errors say it.
class ScopedSilence {
 public:
  ScopedSilence() : cerr_(std::cerr.rdbuf(nullptr)), clog_(std::clog.rdbuf(nullptr)) {}
  ~ScopedSilence() {
    std::cerr.rdbuf(cerr_);
    std::clog.rdbuf(clog_);
  }

 private:
  std::streambuf* cerr_;
  std::streambuf* clog_;
};

}  // namespace

bool load_mesh(const std::string& filename, TriangleMesh& mesh, std::string& error,
               MeshLoadStats* stats) {
  namespace fs = std::filesystem;
  const std::string ext = lower_extension(filename);
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl") {
    error = filename + ": unknown mesh extension '" + ext + "' (expected .obj, .ply, .off, .stl)";
    return false;
  }
  std::error_code ec;
  if (!fs::exists(filename, ec)) {
    error = filename + ": no such file";
    return false;
  }
  if (!fs::is_regular_file(filename, ec)) {
    error = filename + ": not a regular file";
    return false;
  }
  if (!std::ifstream(filename).good()) {
    error = filename + ": cannot open (permission denied?)";
    return false;
  }
  if (fs::file_size(filename, ec) == 0) {
    error = filename + ": empty file";
    return false;
  }

  SoupImporter importer;
  OpenMesh::IO::Options options;
  bool read_ok = false;
  {
    ScopedSilence silence;
    // OpenMesh's readers pick the format by the extension; make it lower case for them.
    read_ok = OpenMesh::IO::IOManager().read(filename, importer, options);
  }
  if (find_text_coordinate_error(filename, ext, error) ||
      (ext == ".obj" && find_obj_index_error(filename, importer.positions.size(), error))) {
    return false;
  }
  if (!read_ok) {
    error = filename + ": cannot parse as " + ext.substr(1) + " (malformed or unsupported file)";
    return false;
  }
  if (importer.bad_indices > 0) {
    error = filename + ": " + std::to_string(importer.bad_indices) +
            " faces with vertex indices out of range";
    return false;
  }
  if (importer.triangles.empty()) {
    error = filename + ": no faces (" + std::to_string(importer.positions.size()) +
            " vertices read; triangle strips and point clouds are not supported)";
    return false;
  }
  for (size_t i = 0; i < importer.positions.size(); ++i) {
    if (!glm::all(glm::isfinite(importer.positions[i]))) {
      error = filename + ": vertex " + std::to_string(i) + " has a NaN or infinite coordinate";
      return false;
    }
  }
  mesh.positions = std::move(importer.positions);
  mesh.triangles = std::move(importer.triangles);
  if (stats) {
    stats->polygons = importer.polygons;
    stats->triangulated = importer.triangulated;
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
