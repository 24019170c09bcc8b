// Orbifold Tutte and disk (circular border) conformal parameterisation with CGAL 5.5. One of the
// few CGAL translation units (the rest of the pipeline sees plain arrays).

#include "preprocess/parameterize.hpp"

// CGAL's sparse solvers are Eigen's (the build links Eigen3::Eigen).
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED
#endif

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Orbifold_Tutte_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <cmath>
#include <unordered_map>

#include "gfield/check.hpp"

namespace gfield {
namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Simple_cartesian<double>;
using Point2 = Kernel::Point_2;
using Point3 = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;
using VertexIndex = SurfaceMesh::Vertex_index;
using SeamEdgeMap = SurfaceMesh::Property_map<SurfaceMesh::Edge_index, bool>;
using SeamVertexMap = SurfaceMesh::Property_map<VertexIndex, bool>;
using SeamMesh = CGAL::Seam_mesh<SurfaceMesh, SeamEdgeMap, SeamVertexMap>;
using SeamVertex = boost::graph_traits<SeamMesh>::vertex_descriptor;
using SparseLU = CGAL::Eigen_solver_traits<
    Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int>>>;

/// SparseLU that factorises a matrix once: CGAL's fixed-border parameterisers solve for u and for
/// v with two linear_solver(A, B, X, D) calls on the same A, which would factorise it twice.
class FactorOnceSparseLU : public SparseLU {
 public:
  bool linear_solver(const Matrix& a, const Vector& b, Vector& x, NT& d) {
    d = 1;
    if (factored_ != &a.eigen_object()) {
      if (!factor(a, d))
        return false;
      factored_ = &a.eigen_object();
    }
    return SparseLU::linear_solver(b, x);
  }

 private:
  const void* factored_ = nullptr;
};

/// Surface_mesh with vertex v = positions[v] and faces in triangle order; false if a face cannot
/// be added (not an oriented manifold).
bool build_surface_mesh(const std::vector<glm::dvec3>& positions,
                        const std::vector<glm::ivec3>& triangles, SurfaceMesh& sm) {
  sm.reserve(positions.size(), 3 * triangles.size() / 2, triangles.size());
  for (const glm::dvec3& p : positions)
    sm.add_vertex(Point3(p.x, p.y, p.z));
  for (const glm::ivec3& t : triangles)
    if (sm.add_face(VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2])) ==
        SurfaceMesh::null_face())
      return false;
  return true;
}

double signed_area(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/// Mirrors the chart across its diagonal (keeps the square and the orbifold cones at (0,0) and
/// (1,1)) when most of its area is clockwise, then counts faults.
void orient_and_count(Chart& chart) {
  GF_CHECK_EQ(chart.corner_uv.size() % 3, size_t(0), "three corner uvs per face");
  double total = 0.0;
  for (size_t f = 0; 3 * f < chart.corner_uv.size(); ++f)
    total +=
        signed_area(chart.corner_uv[3 * f], chart.corner_uv[3 * f + 1], chart.corner_uv[3 * f + 2]);
  if (total < 0.0)
    for (glm::dvec2& uv : chart.corner_uv)
      uv = {uv.y, uv.x};
  count_uv_faults(chart.corner_uv, chart.flipped, chart.degenerate);
}

bool all_finite(const std::vector<glm::dvec2>& uvs) {
  for (const glm::dvec2& uv : uvs)
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
      return false;
  return true;
}

/// Tutte embedding (uniform weights) of a disk whose border has exactly three vertices, mapped to
/// the corners (0,0), (1,0), (0,1): one-to-one by Tutte's theorem. Chart uvs per corner.
std::vector<glm::dvec2> tutte_triangle_border(const SurfaceMesh& sm,
                                              SurfaceMesh::Halfedge_index border,
                                              const std::vector<glm::ivec3>& triangles) {
  const size_t n = sm.number_of_vertices();
  std::vector<glm::dvec2> uv(n, glm::dvec2(0.0));
  std::vector<char> fixed(n, 0);
  const glm::dvec2 corners[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
  int k = 0;
  for (auto h : CGAL::halfedges_around_face(border, sm)) {
    const size_t v = size_t(sm.target(h));
    uv[v] = corners[k++ % 3];
    fixed[v] = 1;
  }
  std::vector<int> unknown(n, -1);
  int count = 0;
  for (size_t v = 0; v < n; ++v)
    if (!fixed[v])
      unknown[v] = count++;
  if (count > 0) {
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd bu = Eigen::VectorXd::Zero(count), bv = Eigen::VectorXd::Zero(count);
    for (size_t v = 0; v < n; ++v) {
      if (fixed[v])
        continue;
      const int row = unknown[v];
      double degree = 0.0;
      for (auto w : CGAL::vertices_around_target(sm.halfedge(VertexIndex(v)), sm)) {
        degree += 1.0;
        if (fixed[size_t(w)]) {
          bu[row] += uv[size_t(w)].x;
          bv[row] += uv[size_t(w)].y;
        } else {
          entries.emplace_back(row, unknown[size_t(w)], -1.0);
        }
      }
      entries.emplace_back(row, row, degree);
    }
    Eigen::SparseMatrix<double> a(count, count);
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(a);
    const Eigen::VectorXd xu = solver.solve(bu), xv = solver.solve(bv);
    for (size_t v = 0; v < n; ++v)
      if (!fixed[v])
        uv[v] = {xu[unknown[v]], xv[unknown[v]]};
  }
  std::vector<glm::dvec2> corner_uv(3 * triangles.size());
  for (size_t f = 0; f < triangles.size(); ++f)
    for (int c = 0; c < 3; ++c)
      corner_uv[3 * f + c] = uv[size_t(triangles[f][c])];
  return corner_uv;
}
}  // namespace

std::string parameterization_error_message(int code) {
  switch (code) {
    case SMP::OK:
      return "success";
    case SMP::ERROR_EMPTY_MESH:
      return "the mesh is empty";
    case SMP::ERROR_NON_TRIANGULAR_MESH:
      return "the mesh is not a triangle mesh";
    case SMP::ERROR_NO_TOPOLOGICAL_DISC:
      return "the mesh is not a topological disk";
    case SMP::ERROR_NO_TOPOLOGICAL_BALL:
      return "the mesh is not a topological sphere";
    case SMP::ERROR_BORDER_TOO_SHORT:
      return "the border is too short for a square border";
    case SMP::ERROR_NON_CONVEX_BORDER:
      return "the method needs a convex border";
    case SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM:
      return "the linear system cannot be solved (degenerate triangles?)";
    case SMP::ERROR_NO_1_TO_1_MAPPING:
      return "the map is not one-to-one (flipped triangles)";
    case SMP::ERROR_WRONG_PARAMETER:
      return "a parameter is invalid";
    default:
      return "unknown CGAL parameterization error " + std::to_string(code);
  }
}

void count_uv_faults(const std::vector<glm::dvec2>& corner_uv, size_t& flipped,
                     size_t& degenerate) {
  double total = 0.0;
  const size_t faces = corner_uv.size() / 3;
  std::vector<double> area(faces);
  for (size_t f = 0; f < faces; ++f) {
    area[f] = signed_area(corner_uv[3 * f], corner_uv[3 * f + 1], corner_uv[3 * f + 2]);
    total += std::abs(area[f]);
  }
  const double epsilon = 1e-12 * total;
  flipped = degenerate = 0;
  for (double a : area) {
    if (!(std::abs(a) > epsilon))
      ++degenerate;
    else if (a < 0.0)
      ++flipped;
  }
}

namespace {

/// The orbifold's three cones by farthest-point sampling (chart.cones) and the seam: a path
/// first -> duplicated and a second path duplicated -> second avoiding the first, so that the
/// seam is a simple path.
bool orbifold_seam(const TriangleMesh& component, Chart& chart, std::vector<int>& path1,
                   std::vector<int>& path2, std::string& error) {
  const std::vector<int> far = farthest_points(component, 3);
  if (far[0] == far[1] || far[1] == far[2] || far[0] == far[2]) {
    error = "orbifold: the component has fewer than three distinct cone vertices";
    return false;
  }
  const int first = far[0], duplicated = far[2], second = far[1];
  path1 = shortest_path(component, first, duplicated);
  std::vector<char> blocked(component.positions.size(), 0);
  for (int v : path1)
    blocked[v] = v != duplicated;
  path2 = shortest_path(component, duplicated, second, blocked);
  if (path1.empty() || path2.empty()) {
    error = "orbifold: no seam path between the cones";
    return false;
  }
  chart.cones = {first, duplicated, second};
  return true;
}

using SeamVertexIndices = boost::associative_property_map<std::unordered_map<SeamVertex, int>>;

/// One Orbifold Tutte solve with `weights`: the corner uvs into `chart` (in [0,1]^2). True when
/// it is finite and has no flipped face; `error` says why not.
bool solve_orbifold(const TriangleMesh& component, const SurfaceMesh& sm, SeamMesh& mesh,
                    const std::unordered_map<SeamVertex, SMP::Cone_type>& cones,
                    SeamVertexIndices vimap, SMP::Weight_type weights, Chart& chart,
                    std::string& error) {
  std::unordered_map<SeamVertex, Point2> uvs;
  boost::associative_property_map<std::unordered_map<SeamVertex, Point2>> uvmap(uvs);
  SMP::Orbifold_Tutte_parameterizer_3<SeamMesh, SparseLU> parameterizer(SMP::Square, weights);
  const auto border = PMP::longest_border(mesh).first;
  const SMP::Error_code code = parameterizer.parameterize(mesh, border, cones, uvmap, vimap);
  if (code != SMP::OK) {
    error = "orbifold: " + parameterization_error_message(code);
    return false;
  }
  chart.corner_uv.assign(3 * component.triangles.size(), glm::dvec2(0.0));
  for (auto f : sm.faces()) {
    const glm::ivec3& t = component.triangles[size_t(f)];
    for (auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const int v = int(CGAL::target(h.tmhd, sm));
      const int corner = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      const Point2& p = get(uvmap, target(h, mesh));
      // CGAL's square orbifold tile has its unique cones at (-1,-1) and (1,1).
      chart.corner_uv[3 * size_t(f) + corner] = {(p.x() + 1.0) / 2.0, (p.y() + 1.0) / 2.0};
    }
  }
  if (!all_finite(chart.corner_uv)) {
    error = "orbifold: the solution is not finite (degenerate triangles)";
    return false;
  }
  chart.weights = weights == SMP::Cotangent ? "cotangent" : "mean value";
  orient_and_count(chart);
  if (chart.flipped == 0)
    return true;
  error = "orbifold: " + std::to_string(chart.flipped) + " flipped faces";
  return false;
}

}  // namespace

bool parameterize_orbifold(const TriangleMesh& component, Chart& chart, std::string& error) {
  chart = {};
  chart.orbifold = true;
  SurfaceMesh sm;
  if (!build_surface_mesh(component.positions, component.triangles, sm)) {
    error = "orbifold: the component is not an oriented manifold";
    return false;
  }
  std::vector<int> path1, path2;
  if (!orbifold_seam(component, chart, path1, path2, error))
    return false;
  SeamEdgeMap seam_edges =
      sm.add_property_map<SurfaceMesh::Edge_index, bool>("e:seam", false).first;
  SeamVertexMap seam_vertices = sm.add_property_map<VertexIndex, bool>("v:seam", false).first;
  SeamMesh mesh(sm, seam_edges, seam_vertices);
  for (const std::vector<int>* path : {&path1, &path2})
    for (const Edge& e : path_edges(*path)) {
      if (!mesh.add_seam(VertexIndex(e[0]), VertexIndex(e[1]))) {
        error = "orbifold: cannot add a seam edge";
        return false;
      }
      ++chart.seam_edges;
    }
  std::unordered_map<SeamVertex, int> indices;
  for (SeamVertex v : vertices(mesh))
    indices.emplace(v, int(indices.size()));
  std::unordered_map<SeamVertex, SMP::Cone_type> cones;
  const std::vector<VertexIndex> cone_vertices{
      VertexIndex(chart.cones[0]), VertexIndex(chart.cones[1]), VertexIndex(chart.cones[2])};
  if (!SMP::locate_cones(mesh, cone_vertices.begin(), cone_vertices.end(), cones)) {
    error = "orbifold: invalid cones";
    return false;
  }
  // Cotangent weights approximate a conformal map; mean-value weights are always one-to-one.
  for (SMP::Weight_type weights : {SMP::Cotangent, SMP::Mean_value})
    if (solve_orbifold(component, sm, mesh, cones, SeamVertexIndices(indices), weights, chart,
                       error))
      return true;
  return !chart.corner_uv.empty() && all_finite(chart.corner_uv) && chart.flipped == 0;
}

bool parameterize_disk(const TriangleMesh& component, const std::vector<Edge>& cut, Chart& chart,
                       std::string& error) {
  chart = {};
  chart.seam_edges = cut.size();
  const DiskMesh disk = cut_open(component, cut);
  std::vector<glm::dvec3> positions(disk.vertex_origin.size());
  for (size_t v = 0; v < positions.size(); ++v)
    positions[v] = component.positions[disk.vertex_origin[v]];
  SurfaceMesh sm;
  if (!build_surface_mesh(positions, disk.triangles, sm)) {
    error = "disk: the cut component is not an oriented manifold";
    return false;
  }
  std::vector<SurfaceMesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(sm, std::back_inserter(borders));
  const long euler =
      long(sm.number_of_vertices()) - long(sm.number_of_edges()) + long(sm.number_of_faces());
  if (borders.size() != 1 || euler != 1) {
    error = "disk: the cut does not leave a disk (" + std::to_string(borders.size()) +
            " borders, Euler characteristic " + std::to_string(euler) + ")";
    return false;
  }
  if (CGAL::halfedges_around_face(borders[0], sm).size() == 3) {  // three border vertices
    chart.corner_uv = tutte_triangle_border(sm, borders[0], disk.triangles);
    GF_CHECK_EQ(chart.corner_uv.size(), 3 * disk.triangles.size(), "a uv per corner");
    chart.weights = "uniform";
    orient_and_count(chart);
    if (chart.flipped == 0 && all_finite(chart.corner_uv))
      return true;
    error = "disk: the triangle-border Tutte embedding failed";
    return false;
  }
  using Border = SMP::Circular_border_arc_length_parameterizer_3<SurfaceMesh>;
  for (int attempt = 0; attempt < 2; ++attempt) {
    auto uvmap = sm.add_property_map<VertexIndex, Point2>("v:uv", Point2(0, 0)).first;
    SMP::Error_code code;
    if (attempt == 0) {
      SMP::Discrete_conformal_map_parameterizer_3<SurfaceMesh, Border, FactorOnceSparseLU>
          parameterizer;
      code = SMP::parameterize(sm, parameterizer, borders[0], uvmap);
    } else {
      SMP::Mean_value_coordinates_parameterizer_3<SurfaceMesh, Border, FactorOnceSparseLU>
          parameterizer;
      code = SMP::parameterize(sm, parameterizer, borders[0], uvmap);
    }
    if (code == SMP::OK) {
      chart.corner_uv.resize(3 * disk.triangles.size());
      for (size_t f = 0; f < disk.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) {
          const Point2& p = uvmap[VertexIndex(disk.triangles[f][k])];
          chart.corner_uv[3 * f + k] = {p.x(), p.y()};
        }
      sm.remove_property_map(uvmap);
      if (all_finite(chart.corner_uv)) {
        chart.weights = attempt == 0 ? "cotangent" : "mean value";
        orient_and_count(chart);
        if (chart.flipped == 0)
          return true;
        error = "disk: " + std::to_string(chart.flipped) + " flipped faces";
      } else {
        error = "disk: the solution is not finite (degenerate triangles)";
      }
    } else {
      sm.remove_property_map(uvmap);
      error = "disk: " + parameterization_error_message(code);
    }
  }
  return !chart.corner_uv.empty() && all_finite(chart.corner_uv) && chart.flipped == 0;
}

}  // namespace gfield
