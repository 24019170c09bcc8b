#pragma once
// Topology of a triangle soup: components, boundary loops, non-manifold elements, degenerate
// faces, Euler characteristic and genus per component, bounding box.

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include "geometry/mesh_io.hpp"

namespace gfield {

/// One connected component: faces connected through shared edges. A pinched vertex (several
/// fans of faces) counts once per fan, as if the surface were split there.
struct ComponentTopology {
  size_t vertices = 0;  ///< (vertex, fan) pairs of the component's faces
  size_t edges = 0;     ///< distinct undirected edges
  size_t faces = 0;
  size_t boundary_edges = 0;         ///< edges with one face
  size_t boundary_loops = 0;         ///< closed chains of boundary edges
  size_t non_manifold_edges = 0;     ///< edges with more than two faces
  size_t non_manifold_vertices = 0;  ///< vertices whose faces form more than one fan
  bool oriented = true;              ///< every interior edge is used once in each direction
  long euler_characteristic = 0;     ///< V - E + F
  /// (2 - chi - boundary loops) / 2 for an edge-manifold oriented component, else -1.
  long genus = -1;
  double area = 0.0;
  glm::dvec3 bounds_min{0.0};
  glm::dvec3 bounds_max{0.0};
};

struct TopologyReport {
  size_t vertices = 0;  ///< positions in the file
  size_t unreferenced_vertices = 0;
  size_t faces = 0;  ///< triangles
  size_t edges = 0;
  size_t boundary_edges = 0;
  size_t boundary_loops = 0;
  size_t non_manifold_edges = 0;
  size_t non_manifold_vertices = 0;
  size_t degenerate_faces = 0;     ///< repeated corner or zero area
  size_t duplicate_positions = 0;  ///< vertices at the exact position of an earlier vertex
  long euler_characteristic = 0;
  double area = 0.0;
  glm::dvec3 bounds_min{0.0};
  glm::dvec3 bounds_max{0.0};
  std::vector<ComponentTopology> components;  ///< largest (by faces) first

  bool closed() const { return boundary_edges == 0; }
  bool manifold() const { return non_manifold_edges == 0 && non_manifold_vertices == 0; }
};

/// Analyses `mesh` (indices must be in range; load_mesh guarantees it).
TopologyReport analyze_topology(const TriangleMesh& mesh);

/// The report as JSON (the `gfield info --json` schema, see docs/cli.md).
nlohmann::json topology_to_json(const TopologyReport& report);
/// The inverse of topology_to_json. Throws nlohmann::json::exception where `j` is not of that
/// shape.
TopologyReport topology_from_json(const nlohmann::json& j);

/// The report as readable text, one fact per line.
std::string topology_to_text(const TopologyReport& report);

}  // namespace gfield
