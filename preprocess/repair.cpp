// Soup repair (weld, degenerate/duplicate faces, manifold split, orientation) and hole filling
// with CGAL's triangulate_refine_and_fair_hole. One of the few CGAL translation units.

#include "preprocess/repair.hpp"

// CGAL's fairing and sparse solvers use Eigen (the build links Eigen3::Eigen).
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "preprocess/mesh_proxy.hpp"

namespace gfield {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;

struct FaceHash {
  size_t operator()(const std::array<int, 3>& f) const {
    uint64_t h = 1469598103934665603ull;
    for (int v : f)
      h = (h ^ uint64_t(uint32_t(v))) * 1099511628211ull;
    return size_t(h ^ (h >> 29));
  }
};

double triangle_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

/// Turns closed components with negative signed volume outward; returns how many it reversed.
size_t orient_outward(TriangleMesh& mesh) {
  const std::vector<int> component = face_components(mesh);
  const int count =
      component.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
  std::vector<double> volume(count, 0.0);
  std::vector<char> closed(count, 1);
  std::unordered_map<uint64_t, int> directed;
  directed.reserve(3 * mesh.triangles.size());
  auto key = [](int a, int b) { return (uint64_t(uint32_t(a)) << 32) | uint32_t(b); };
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::ivec3& t = mesh.triangles[f];
    const glm::dvec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]],
                     &c = mesh.positions[t[2]];
    volume[component[f]] += glm::dot(a, glm::cross(b, c));
    for (int k = 0; k < 3; ++k)
      directed[key(t[k], t[(k + 1) % 3])] = component[f];
  }
  for (const auto& [edge, c] : directed)
    if (!directed.count(key(int(edge & 0xffffffffu), int(edge >> 32))))
      closed[c] = 0;
  size_t reversed = 0;
  for (int c = 0; c < count; ++c)
    reversed += closed[c] && volume[c] < 0.0;
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    if (closed[component[f]] && volume[component[f]] < 0.0)
      std::swap(mesh.triangles[f][1], mesh.triangles[f][2]);
  return reversed;
}

}  // namespace

std::vector<int> face_components(const TriangleMesh& mesh) {
  std::vector<int> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const glm::ivec3& t : mesh.triangles) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::vector<int> id(mesh.positions.size(), -1), component(mesh.triangles.size());
  int next = 0;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    int& c = id[find(mesh.triangles[f][0])];
    if (c < 0)
      c = next++;
    component[f] = c;
  }
  return component;
}

namespace {

/// The faces of `welded` with a positive area, each vertex triple once (as `faces`), and the
/// input face of each (`kept`); the others counted into `report`.
void proper_faces(const TriangleMesh& welded, std::vector<std::array<int, 3>>& faces,
                  std::vector<int>& kept, RepairReport& report) {
  std::unordered_set<std::array<int, 3>, FaceHash> seen;
  seen.reserve(welded.triangles.size());
  for (size_t input_face = 0; input_face < welded.triangles.size(); ++input_face) {
    const glm::ivec3& t = welded.triangles[input_face];
    const std::array<int, 3> f{t[0], t[1], t[2]};
    const std::vector<glm::dvec3>& p = welded.positions;
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] ||
        triangle_area(p[f[0]], p[f[1]], p[f[2]]) == 0.0) {
      ++report.degenerate_faces;
      continue;
    }
    std::array<int, 3> key = f;
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) {
      ++report.duplicate_faces;
      continue;
    }
    faces.push_back(f);
    kept.push_back(int(input_face));
  }
}

/// `faces` over `positions` as CGAL's soup of the positions they use (the others counted as
/// unreferenced).
void make_soup(const std::vector<glm::dvec3>& positions,
               const std::vector<std::array<int, 3>>& faces, std::vector<Point3>& points,
               std::vector<std::vector<std::size_t>>& polygons, RepairReport& report) {
  std::vector<int> compact(positions.size(), -1);
  polygons.reserve(faces.size());
  for (const auto& f : faces) {
    std::vector<std::size_t> polygon(3);
    for (int k = 0; k < 3; ++k) {
      if (compact[f[k]] < 0) {
        compact[f[k]] = int(points.size());
        const glm::dvec3& p = positions[f[k]];
        points.emplace_back(p.x, p.y, p.z);
      }
      polygon[k] = std::size_t(compact[f[k]]);
    }
    polygons.push_back(std::move(polygon));
  }
  report.unreferenced_positions = positions.size() - points.size();
}

/// The surface mesh's vertices and faces (in their order).
TriangleMesh triangle_mesh(const SurfaceMesh& sm) {
  TriangleMesh mesh;
  mesh.positions.reserve(sm.number_of_vertices());
  for (const auto& v : sm.vertices()) {
    const Point3& p = sm.point(v);
    mesh.positions.emplace_back(p.x(), p.y(), p.z());
  }
  for (const auto& f : sm.faces()) {
    glm::ivec3 t;
    int k = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm))
      t[k++] = int(v);
    mesh.triangles.push_back(t);
  }
  return mesh;
}

/// Fills the boundary loops of `sm` that `holes` asks for (all, or all but the longest of each
/// component), counted into `report`.
void fill_holes(SurfaceMesh& sm, HoleFilling holes, RepairReport& report) {
  std::vector<SurfaceMesh::Halfedge_index> cycles;  // one halfedge per boundary cycle
  PMP::extract_boundary_cycles(sm, std::back_inserter(cycles));
  report.holes_found = cycles.size();
  if (holes == HoleFilling::kNone || cycles.empty())
    return;
  const std::vector<int> component = face_components(triangle_mesh(sm));
  std::vector<double> length(cycles.size(), 0.0);
  std::vector<int> cycle_component(cycles.size());
  std::map<int, size_t> longest;  // component -> cycle
  for (size_t c = 0; c < cycles.size(); ++c) {
    for (auto h : CGAL::halfedges_around_face(cycles[c], sm))
      length[c] +=
          std::sqrt(CGAL::squared_distance(sm.point(sm.source(h)), sm.point(sm.target(h))));
    cycle_component[c] = component[size_t(sm.face(sm.opposite(cycles[c])))];
    auto it = longest.find(cycle_component[c]);
    if (it == longest.end() || length[c] > length[it->second])
      longest[cycle_component[c]] = c;
  }
  for (size_t c = 0; c < cycles.size(); ++c) {
    if (holes == HoleFilling::kAllButLongest && longest[cycle_component[c]] == c)
      continue;
    std::vector<SurfaceMesh::Face_index> patch;
    const bool faired = std::get<0>(PMP::triangulate_refine_and_fair_hole(
        sm, cycles[c], std::back_inserter(patch), CGAL::Emptyset_iterator()));
    if (patch.empty())
      continue;
    ++report.holes_filled;
    report.holes_fair_failed += !faired;
    report.filled_faces += patch.size();
    for (auto f : patch) {
      auto h = sm.halfedge(f);
      report.filled_area += std::sqrt(CGAL::squared_area(
          sm.point(sm.source(h)), sm.point(sm.target(h)), sm.point(sm.target(sm.next(h)))));
    }
  }
}

}  // namespace

bool repair_mesh(const TriangleMesh& input, HoleFilling holes, RepairedMesh& out,
                 std::string& error) {
  out = {};
  RepairReport& report = out.report;
  const TriangleMesh welded = weld_positions(input);
  report.welded_positions = input.positions.size() - welded.positions.size();
  std::vector<std::array<int, 3>> faces;
  std::vector<int> kept;  // the input face of each of `faces`
  proper_faces(welded, faces, kept, report);
  if (faces.empty()) {
    error = "no face with a positive area (the mesh is degenerate: zero area or collinear points)";
    return false;
  }
  std::vector<Point3> points;
  std::vector<std::vector<std::size_t>> polygons;
  make_soup(welded.positions, faces, points, polygons, report);
  // Split non-manifold vertices and orient each component consistently.
  const size_t before = points.size();
  PMP::orient_polygon_soup(points, polygons);
  report.split_vertices = points.size() - before;
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    error = "the mesh is not an oriented manifold after repair (non-manifold edges remain)";
    return false;
  }
  SurfaceMesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
  if (sm.number_of_faces() != polygons.size()) {
    error = "the mesh is not an oriented manifold after repair";
    return false;
  }
  out.input_faces = sm.number_of_faces();
  fill_holes(sm, holes, report);
  out.mesh = triangle_mesh(sm);
  TriangleMesh& mesh = out.mesh;
  // Surface_mesh keeps the soup's faces in their order and appends the hole fillings.
  out.source_face.assign(mesh.triangles.size(), -1);
  std::copy_n(kept.begin(), std::min(kept.size(), out.input_faces), out.source_face.begin());
  report.reversed_components = orient_outward(mesh);
  for (const glm::ivec3& t : mesh.triangles)
    report.area += triangle_area(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
  return true;
}

}  // namespace gfield
