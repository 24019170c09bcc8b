#pragma once
// Repair of a triangle soup before parameterisation: weld exactly coincident positions, drop
// degenerate and duplicate faces, split non-manifold vertices and orient every component
// consistently (closed components outward), then fill holes with CGAL's refine-and-fair so that
// each component is closed or has a single boundary loop.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"

namespace gfield {

/// Which boundary loops are filled. kAllButLongest keeps the longest loop of each component open
/// (it becomes the border of a disk chart); kAll closes every component; kNone fills nothing.
enum class HoleFilling { kAllButLongest, kAll, kNone };

struct RepairReport {
  size_t welded_positions = 0;        ///< positions merged into an earlier identical position
  size_t unreferenced_positions = 0;  ///< positions no face uses (dropped)
  size_t degenerate_faces = 0;        ///< faces with a repeated corner or zero area (dropped)
  size_t duplicate_faces = 0;         ///< faces over the same three vertices as an earlier face
  size_t split_vertices = 0;          ///< vertices duplicated to make the soup manifold
  size_t reversed_components = 0;     ///< closed components turned outward
  size_t holes_found = 0;             ///< boundary loops after the steps above
  size_t holes_filled = 0;
  size_t holes_fair_failed = 0;  ///< filled, but the fairing step failed (patch kept unfaired)
  size_t filled_faces = 0;       ///< triangles added by hole filling
  double filled_area = 0.0;      ///< area of those triangles (mesh units squared)
  double area = 0.0;             ///< area of the repaired mesh, fill included
};

/// The repaired mesh. Faces [0, input_faces) come from the input soup, the rest fill holes.
struct RepairedMesh {
  TriangleMesh mesh;
  size_t input_faces = 0;
  /// Per face of `mesh`: the input face it is (its corners at the same positions, in any order),
  /// or -1 for a face that fills a hole.
  std::vector<int> source_face;
  RepairReport report;
};

/// Components of faces connected through shared vertices (union-find): F component ids, numbered
/// in the order of their first face.
std::vector<int> face_components(const TriangleMesh& mesh);

/// Repairs `input`. False with an error (no file name; the caller prefixes it) when nothing is
/// left (every face degenerate) or the soup cannot be made an oriented manifold.
bool repair_mesh(const TriangleMesh& input, HoleFilling holes, RepairedMesh& out,
                 std::string& error);

}  // namespace gfield
