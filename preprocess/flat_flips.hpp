#pragma once
// Edge flips where a mesh is flat: an edge whose two faces lie within a tolerance of one plane is
// replaced by the quad's other diagonal when it is not locally Delaunay (its opposite angles sum
// to more than pi). A simplifier's collapses on flat, over-tessellated surfaces (a midpoint-
// subdivided mesh) leave needles and zero-area faces with three collinear corners; repair would
// drop those and open a hole per face, and the charts' conformal maps would stretch around the
// needles. The flips remove both without moving the surface by more than the tolerance.

#include <cstddef>

#include "geometry/mesh_io.hpp"

namespace gfield {

struct FlatFlipsReport {
  size_t flips = 0;
  /// Faces of (nearly) zero area left (smallest angle below 1e-4 radians).
  size_t needles = 0;
};

/// Flips, in place, every interior edge of `mesh` (exactly two faces, consistently oriented) whose
/// flip keeps the surface within `tolerance` (mesh units: the height of the tetrahedron of the
/// quad's four corners over its largest face) and keeps both new faces facing the old pair's
/// side, while the edge is not locally Delaunay, until none is left or 8 flips per face were made.
/// Face count, vertex positions and orientation are unchanged; faces are rewritten in place.
FlatFlipsReport flip_flat_edges(TriangleMesh& mesh, double tolerance);

}  // namespace gfield
