#pragma once
// Cutting a connected, oriented, manifold triangle mesh into a topological disk: a tree-cotree
// cut graph for genus >= 1, shortest paths on the edge graph (seams and slits), and the cut itself
// (vertices on the cut are duplicated, one copy per side).

#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"

namespace gfield {

/// An undirected mesh edge as its two vertex indices.
using Edge = glm::ivec2;

/// Tree-cotree cut graph (Eppstein 2003, Erickson & Whittlesey 2005) of a connected oriented
/// manifold mesh that is closed or has boundary loops: a BFS tree of the vertices rooted at
/// `root` (or at every boundary vertex when there is a boundary), a spanning tree of the faces
/// across the remaining interior edges, and for each of the 2g leftover edges the loop it closes
/// in the vertex tree; dangling branches are pruned. Cutting along the result (and the boundary)
/// leaves a disk. Empty for genus 0.
std::vector<Edge> tree_cotree_cut(const TriangleMesh& mesh, int root = 0);

/// Shortest path along edges (Euclidean edge lengths, Dijkstra) from `from` to `to`, avoiding the
/// vertices marked in `blocked` (may be empty; `from`/`to` are never blocked). The vertices of the
/// path from `from` to `to`; empty if `to` cannot be reached.
std::vector<int> shortest_path(const TriangleMesh& mesh, int from, int to,
                               const std::vector<char>& blocked = {});

/// Geodesic (edge-graph) distances from the `sources` to every vertex (infinity if unreachable).
std::vector<double> edge_distances(const TriangleMesh& mesh, const std::vector<int>& sources);

/// `count` vertices spread by farthest-point sampling on the edge graph, the first being the
/// vertex farthest from vertex 0.
std::vector<int> farthest_points(const TriangleMesh& mesh, int count);

/// A disk cut from a mesh: copies of the mesh vertices (one per side of the cut) and the mesh's
/// triangles over them, in the same order.
struct DiskMesh {
  std::vector<int> vertex_origin;     ///< disk vertex -> mesh vertex
  std::vector<glm::ivec3> triangles;  ///< F triangles over disk vertices
};

/// Cuts `mesh` along `cut` (edges of the mesh): around every vertex, the corners between two cut
/// or boundary edges become one disk vertex.
DiskMesh cut_open(const TriangleMesh& mesh, const std::vector<Edge>& cut);

/// Boundary edges (edges with one face), each as (source, target) of its face's winding.
std::vector<Edge> boundary_edges(const TriangleMesh& mesh);

/// Edges of a vertex path (consecutive pairs).
std::vector<Edge> path_edges(const std::vector<int>& path);

}  // namespace gfield
