// Tree-cotree cut graphs, edge-graph shortest paths and cutting a mesh open along edges.

#include "preprocess/cut_graph.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>

#include "geometry/edge_key.hpp"
#include "gfield/check.hpp"

namespace gfield {
namespace {

/// Undirected edges with their faces (one or two) and the vertex-edge adjacency.
struct EdgeGraph {
  std::vector<Edge> edges;
  std::vector<glm::ivec2> edge_faces;          ///< second = -1 on the boundary
  std::vector<std::vector<int>> vertex_edges;  ///< edges at each vertex, in creation order
  std::vector<glm::ivec3> face_edges;          ///< edge of (corner k, corner k+1)
  std::unordered_map<uint64_t, int> index;

  explicit EdgeGraph(const TriangleMesh& mesh) {
    vertex_edges.resize(mesh.positions.size());
    face_edges.resize(mesh.triangles.size());
    index.reserve(mesh.triangles.size() * 2);
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
      const glm::ivec3& t = mesh.triangles[f];
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        auto [it, inserted] = index.emplace(edge_key(a, b), int(edges.size()));
        if (inserted) {
          edges.push_back({std::min(a, b), std::max(a, b)});
          edge_faces.push_back({int(f), -1});
          vertex_edges[a].push_back(it->second);
          vertex_edges[b].push_back(it->second);
        } else {
          edge_faces[it->second][1] = int(f);
        }
        face_edges[f][k] = it->second;
      }
    }
  }
  int other(int e, int v) const { return edges[e][0] == v ? edges[e][1] : edges[e][0]; }
  bool boundary(int e) const { return edge_faces[e][1] < 0; }
};

double edge_length(const TriangleMesh& mesh, int a, int b) {
  return glm::length(mesh.positions[a] - mesh.positions[b]);
}

}  // namespace

std::vector<Edge> boundary_edges(const TriangleMesh& mesh) {
  std::unordered_map<uint64_t, char> directed;
  for (const glm::ivec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      directed[half_edge_key(t[k], t[(k + 1) % 3])] = 1;
  std::vector<Edge> edges;
  for (const glm::ivec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (!directed.count(half_edge_key(b, a)))
        edges.push_back({a, b});
    }
  return edges;
}

std::vector<Edge> path_edges(const std::vector<int>& path) {
  std::vector<Edge> edges;
  for (size_t i = 1; i < path.size(); ++i)
    edges.push_back({path[i - 1], path[i]});
  return edges;
}

namespace {

/// The vertex BFS tree of the tree-cotree cut, rooted at every boundary vertex when there is a
/// boundary (else at `root`), across interior edges.
struct VertexTree {
  std::vector<int> parent_edge;   ///< per vertex, -1 at a root
  std::vector<char> in_tree;      ///< per edge
  std::vector<char> on_boundary;  ///< per vertex
};

VertexTree vertex_tree(const EdgeGraph& graph, size_t vertices, int root) {
  VertexTree tree;
  tree.parent_edge.assign(vertices, -1);
  tree.in_tree.assign(graph.edges.size(), 0);
  tree.on_boundary.assign(vertices, 0);
  std::vector<char> reached(vertices, 0);
  std::deque<int> queue;
  for (size_t e = 0; e < graph.edges.size(); ++e)
    if (graph.boundary(int(e)))
      tree.on_boundary[graph.edges[e][0]] = tree.on_boundary[graph.edges[e][1]] = 1;
  for (size_t v = 0; v < vertices; ++v)
    if (tree.on_boundary[v]) {
      reached[v] = 1;
      queue.push_back(int(v));
    }
  if (queue.empty()) {
    reached[root] = 1;
    queue.push_back(root);
  }
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop_front();
    for (int e : graph.vertex_edges[v]) {
      const int w = graph.other(e, v);
      if (reached[w] || graph.boundary(e))
        continue;
      reached[w] = 1;
      tree.parent_edge[w] = e;
      tree.in_tree[e] = 1;
      queue.push_back(w);
    }
  }
  for (size_t v = 0; v < vertices; ++v)
    GF_CHECK(tree.parent_edge[v] < 0 || graph.other(tree.parent_edge[v], int(v)) != int(v),
             "a tree edge joins its vertex to another");
  return tree;
}

/// The face spanning tree across interior edges outside the vertex tree: per edge, 1 when in it.
std::vector<char> face_cotree(const EdgeGraph& graph, size_t faces,
                              const std::vector<char>& in_tree) {
  std::vector<char> face_reached(faces, 0), in_cotree(graph.edges.size(), 0);
  size_t trees = 0, cotree_edges = 0;
  for (size_t start = 0; start < faces; ++start) {
    if (face_reached[start])
      continue;
    face_reached[start] = 1;
    ++trees;
    std::deque<int> queue{int(start)};
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k) {
        const int e = graph.face_edges[f][k];
        if (in_tree[e] || graph.boundary(e))
          continue;
        const int g = graph.edge_faces[e][0] == f ? graph.edge_faces[e][1] : graph.edge_faces[e][0];
        if (face_reached[g])
          continue;
        face_reached[g] = 1;
        in_cotree[e] = 1;
        ++cotree_edges;
        queue.push_back(g);
      }
    }
  }
  GF_CHECK_EQ(cotree_edges + trees, faces, "a spanning forest: one edge fewer than faces per tree");
  return in_cotree;
}

/// Each edge in neither tree closes a loop through the vertex tree: the cut is the union of
/// those loops (each a symmetric difference of the two paths to the root, so a shared stem
/// cancels). Per edge, 1 when cut.
std::vector<char> loop_edges(const EdgeGraph& graph, const VertexTree& tree,
                             const std::vector<char>& in_cotree) {
  std::vector<char> in_cut(graph.edges.size(), 0), in_loop(graph.edges.size(), 0);
  std::vector<int> loop;
  for (size_t e = 0; e < graph.edges.size(); ++e) {
    if (tree.in_tree[e] || in_cotree[e] || graph.boundary(int(e)))
      continue;
    loop.assign(1, int(e));
    for (int end = 0; end < 2; ++end) {
      int v = graph.edges[e][end];
      while (tree.parent_edge[v] >= 0) {
        loop.push_back(tree.parent_edge[v]);
        v = graph.other(tree.parent_edge[v], v);
      }
    }
    for (int l : loop)
      in_loop[l] ^= 1;
    for (int l : loop) {
      in_cut[l] |= in_loop[l];
      in_loop[l] = 0;
    }
  }
  return in_cut;
}

/// Removes dangling branches of the cut (degree-1 vertices off the boundary).
void prune_branches(const EdgeGraph& graph, const std::vector<char>& on_boundary,
                    std::vector<char>& in_cut) {
  std::vector<int> degree(on_boundary.size(), 0);
  for (size_t e = 0; e < graph.edges.size(); ++e)
    if (in_cut[e])
      ++degree[graph.edges[e][0]], ++degree[graph.edges[e][1]];
  std::vector<int> leaves;
  for (size_t v = 0; v < degree.size(); ++v)
    if (degree[v] == 1 && !on_boundary[v])
      leaves.push_back(int(v));
  while (!leaves.empty()) {
    const int v = leaves.back();
    leaves.pop_back();
    if (degree[v] != 1)
      continue;
    for (int e : graph.vertex_edges[v]) {
      if (!in_cut[e])
        continue;
      in_cut[e] = 0;
      --degree[v];
      const int w = graph.other(e, v);
      if (--degree[w] == 1 && !on_boundary[w])
        leaves.push_back(w);
      break;
    }
  }
}

}  // namespace

std::vector<Edge> tree_cotree_cut(const TriangleMesh& mesh, int root) {
  const EdgeGraph graph(mesh);
  const VertexTree tree = vertex_tree(graph, mesh.positions.size(), root);
  const std::vector<char> in_cotree = face_cotree(graph, mesh.triangles.size(), tree.in_tree);
  std::vector<char> in_cut = loop_edges(graph, tree, in_cotree);
  prune_branches(graph, tree.on_boundary, in_cut);
  std::vector<Edge> cut;
  for (size_t e = 0; e < graph.edges.size(); ++e)
    if (in_cut[e])
      cut.push_back(graph.edges[e]);
  return cut;
}

std::vector<double> edge_distances(const TriangleMesh& mesh, const std::vector<int>& sources) {
  const EdgeGraph graph(mesh);
  std::vector<double> distance(mesh.positions.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int s : sources) {
    distance[s] = 0.0;
    queue.push({0.0, s});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v])
      continue;
    for (int e : graph.vertex_edges[v]) {
      const int w = graph.other(e, v);
      const double dw = d + edge_length(mesh, v, w);
      if (dw < distance[w]) {
        distance[w] = dw;
        queue.push({dw, w});
      }
    }
  }
  return distance;
}

std::vector<int> shortest_path(const TriangleMesh& mesh, int from, int to,
                               const std::vector<char>& blocked) {
  const EdgeGraph graph(mesh);
  std::vector<double> distance(mesh.positions.size(), std::numeric_limits<double>::infinity());
  std::vector<int> previous(mesh.positions.size(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  distance[from] = 0.0;
  queue.push({0.0, from});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v])
      continue;
    if (v == to)
      break;
    for (int e : graph.vertex_edges[v]) {
      const int w = graph.other(e, v);
      if (w != to && !blocked.empty() && blocked[w])
        continue;
      const double dw = d + edge_length(mesh, v, w);
      if (dw < distance[w]) {
        distance[w] = dw;
        previous[w] = v;
        queue.push({dw, w});
      }
    }
  }
  if (from != to && previous[to] < 0)
    return {};
  std::vector<int> path{to};
  while (path.back() != from)
    path.push_back(previous[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

std::vector<int> farthest_points(const TriangleMesh& mesh, int count) {
  std::vector<int> points;
  std::vector<double> distance = edge_distances(mesh, {0});
  auto farthest = [&] {
    int best = 0;
    for (size_t v = 0; v < distance.size(); ++v)
      if (std::isfinite(distance[v]) && distance[v] > distance[best])
        best = int(v);
    return best;
  };
  points.push_back(farthest());
  while (int(points.size()) < count) {
    distance = edge_distances(mesh, points);
    points.push_back(farthest());
  }
  return points;
}

DiskMesh cut_open(const TriangleMesh& mesh, const std::vector<Edge>& cut) {
  const EdgeGraph graph(mesh);
  std::vector<char> is_cut(graph.edges.size(), 0);
  for (const Edge& e : cut) {
    auto it = graph.index.find(edge_key(e[0], e[1]));
    if (it != graph.index.end())
      is_cut[it->second] = 1;
  }
  // Corners 3f + k; join the two corners at vertex v on either side of every uncut interior edge.
  const size_t nc = 3 * mesh.triangles.size();
  std::vector<int> parent(nc);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  auto corner_at = [&](int f, int v) {
    const glm::ivec3& t = mesh.triangles[f];
    return 3 * f + (t[0] == v ? 0 : t[1] == v ? 1 : 2);
  };
  for (size_t e = 0; e < graph.edges.size(); ++e) {
    if (is_cut[e] || graph.boundary(int(e)))
      continue;
    const int f = graph.edge_faces[e][0], g = graph.edge_faces[e][1];
    for (int end = 0; end < 2; ++end) {
      const int v = graph.edges[e][end];
      const int a = find(corner_at(f, v)), b = find(corner_at(g, v));
      if (a != b)
        parent[std::max(a, b)] = std::min(a, b);
    }
  }
  DiskMesh disk;
  disk.triangles.resize(mesh.triangles.size());
  std::vector<int> vertex_of_class(nc, -1);
  for (size_t c = 0; c < nc; ++c) {
    int& v = vertex_of_class[find(int(c))];
    if (v < 0) {
      v = int(disk.vertex_origin.size());
      disk.vertex_origin.push_back(mesh.triangles[c / 3][c % 3]);
    }
    disk.triangles[c / 3][c % 3] = v;
  }
  return disk;
}

}  // namespace gfield
