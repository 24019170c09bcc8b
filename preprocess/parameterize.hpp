#pragma once
// Conformal parameterisation of one connected component into a square chart, with CGAL:
//  - orbifold: closed genus-0 components, Orbifold Tutte embedding of square type (Aigerman &
//    Lipman 2015): three cones chosen by farthest-point sampling, a seam of two shortest paths.
//    The chart tiles the plane under 90-degree rotations about its corners (0,0) and (1,1), so
//    the unit square is filled exactly by pieces of the tiling and the seam is continuous.
//  - disk: a disk (cut along `cut` first) mapped with a discrete conformal map, its border spread
//    by arc length over the circle inscribed in the unit square (a square border puts the three
//    corners of border "ear" triangles on one side, collapsing them: measured 34-220 degenerate
//    faces per mesh, and 2-5x larger p99 reconstruction errors, than with the circle);
//    mean-value coordinates (always one-to-one for a convex border) when the conformal map flips
//    faces; a border of three vertices gets a uniform Tutte embedding in a right triangle.
// The chart is oriented counter-clockwise (mirrored if needed) so flipped faces are those with a
// negative signed uv area.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"
#include "preprocess/cut_graph.hpp"

namespace gfield {

struct Chart {
  /// 3F chart uvs, corner c of triangle f at 3f + c. Square charts lie in [0,1]^2; orbifold charts
  /// are one tile of the orbifold tiling (its union with its rotated copies covers [0,1]^2).
  std::vector<glm::dvec2> corner_uv;
  bool orbifold = false;
  std::string weights;     ///< "cotangent" or "mean value"
  size_t flipped = 0;      ///< faces with negative signed uv area
  size_t degenerate = 0;   ///< faces with (near) zero uv area
  std::vector<int> cones;  ///< orbifold: the three cone vertices (first unique, duplicated, second)
  size_t seam_edges = 0;   ///< edges cut open (orbifold seam, cut graph or slit)
};

/// Orbifold Tutte embedding of a closed genus-0 component (connected, oriented, manifold).
/// False with an error in words when CGAL fails.
bool parameterize_orbifold(const TriangleMesh& component, Chart& chart, std::string& error);

/// Conformal map of `component` cut along `cut` (which, with the boundary, must leave a disk) onto
/// the disk inscribed in the unit square. False with an error in words when CGAL fails.
bool parameterize_disk(const TriangleMesh& component, const std::vector<Edge>& cut, Chart& chart,
                       std::string& error);

/// CGAL's Surface_mesh_parameterization::Error_code in words (CGAL's own get_error_message is off
/// by one for codes >= 4).
std::string parameterization_error_message(int code);

/// Counts flipped (negative) and degenerate (|area| <= 1e-12 of the chart area) uv triangles.
void count_uv_faults(const std::vector<glm::dvec2>& corner_uv, size_t& flipped, size_t& degenerate);

}  // namespace gfield
