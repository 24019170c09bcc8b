#include "preprocess/topology.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>

#include "geometry/edge_key.hpp"

namespace gfield {

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[size_t(x)] != x) {
      parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
      x = parent[size_t(x)];
    }
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) {
      parent[size_t(std::max(a, b))] = std::min(a, b);
    }
  }
};

// Use of one undirected edge: faces on it, and how often it runs low -> high index.
struct EdgeUse {
  int faces = 0;
  int low_to_high = 0;
  bool counted = false;  // already attributed to a component
};

bool has_repeated_corner(const glm::ivec3& t) {
  return t.x == t.y || t.y == t.z || t.x == t.z;
}

/// Bounds over the referenced vertices, unreferenced vertices, degenerate faces and the area
/// into `r`; the F face areas.
std::vector<double> measure_faces(const TriangleMesh& mesh, TopologyReport& r) {
  std::vector<char> referenced(mesh.positions.size(), 0);
  for (const glm::ivec3& t : mesh.triangles)
    for (int c = 0; c < 3; ++c)
      referenced[size_t(t[c])] = 1;
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    if (referenced[v]) {
      lo = glm::min(lo, mesh.positions[v]);
      hi = glm::max(hi, mesh.positions[v]);
    } else {
      ++r.unreferenced_vertices;
    }
  }
  r.bounds_min = lo;
  r.bounds_max = hi;
  const double diag2 = glm::dot(hi - lo, hi - lo);
  std::vector<double> face_area(mesh.triangles.size());
  for (size_t f = 0; f < face_area.size(); ++f) {
    const glm::ivec3& t = mesh.triangles[f];
    const glm::dvec3 e1 = mesh.positions[size_t(t.y)] - mesh.positions[size_t(t.x)];
    const glm::dvec3 e2 = mesh.positions[size_t(t.z)] - mesh.positions[size_t(t.x)];
    face_area[f] = 0.5 * glm::length(glm::cross(e1, e2));
    if (has_repeated_corner(t) || face_area[f] <= 1e-14 * diag2)
      ++r.degenerate_faces;
    r.area += face_area[f];
  }
  return face_area;
}

/// Vertices at the exact position of an earlier vertex.
size_t count_duplicate_positions(const TriangleMesh& mesh) {
  std::vector<std::array<double, 3>> sorted(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    sorted[v] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z};
  std::sort(sorted.begin(), sorted.end());
  size_t duplicates = 0;
  for (size_t k = 1; k < sorted.size(); ++k)
    duplicates += sorted[k] == sorted[k - 1] ? 1 : 0;
  return duplicates;
}

/// Every undirected edge's use. Faces with a repeated corner contribute only their proper edges.
std::unordered_map<uint64_t, EdgeUse> edge_uses(const TriangleMesh& mesh) {
  std::unordered_map<uint64_t, EdgeUse> edges;
  edges.reserve(mesh.triangles.size() * 2);
  for (const glm::ivec3& t : mesh.triangles) {
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      if (a == b)
        continue;
      EdgeUse& use = edges[edge_key(a, b)];
      ++use.faces;
      use.low_to_high += a < b ? 1 : 0;
    }
  }
  return edges;
}

/// Fans: around each vertex, faces linked through the edges they share at that vertex. A vertex
/// with more than one fan is pinched (non-manifold) and counts once per fan, i.e. the surface is
/// analysed as if pinched vertices were split. fan_of[v][k] is the fan (a local index: the
/// smallest k of its faces) of the k-th face around v, vertex_faces[v][k].
struct Fans {
  std::vector<std::vector<int>> vertex_faces;
  std::vector<std::vector<int>> fan_of;
  /// The fan of face f around vertex v.
  int at(int v, int f) const {
    const std::vector<int>& around = vertex_faces[size_t(v)];
    return fan_of[size_t(v)][size_t(std::find(around.begin(), around.end(), f) - around.begin())];
  }
};

Fans vertex_fans(const TriangleMesh& mesh) {
  Fans fans;
  fans.vertex_faces.resize(mesh.positions.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::ivec3& t = mesh.triangles[f];
    if (!has_repeated_corner(t))
      for (int c = 0; c < 3; ++c)
        fans.vertex_faces[size_t(t[c])].push_back(int(f));
  }
  fans.fan_of.resize(mesh.positions.size());
  std::vector<std::pair<int, int>> corners;  // (other corner, local face index), sorted
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const std::vector<int>& around = fans.vertex_faces[v];
    UnionFind fan(around.size());
    corners.clear();
    for (size_t k = 0; k < around.size(); ++k) {
      const glm::ivec3& t = mesh.triangles[size_t(around[k])];
      for (int c = 0; c < 3; ++c)
        if (t[c] != int(v))
          corners.emplace_back(t[c], int(k));
    }
    std::sort(corners.begin(), corners.end());
    for (size_t i = 1; i < corners.size(); ++i)  // faces sharing an edge at v share a fan
      if (corners[i].first == corners[i - 1].first)
        fan.unite(corners[i - 1].second, corners[i].second);
    fans.fan_of[v].resize(around.size());
    for (size_t k = 0; k < around.size(); ++k)
      fans.fan_of[v][k] = fan.find(int(k));
  }
  return fans;
}

/// Components: faces connected through shared edges, with their faces and area counted.
struct Components {
  UnionFind face_sets;
  std::unordered_map<int, size_t> index_of_root;
  std::vector<ComponentTopology> list;

  explicit Components(size_t faces) : face_sets(faces) {}
  /// Index in `list` of the component of `face` (made on first use).
  size_t index(int face) {
    auto [it, inserted] = index_of_root.emplace(face_sets.find(face), list.size());
    if (inserted) {
      list.emplace_back();
      list.back().bounds_min = glm::dvec3(std::numeric_limits<double>::max());
      list.back().bounds_max = glm::dvec3(std::numeric_limits<double>::lowest());
    }
    return it->second;
  }
  ComponentTopology& of(int face) { return list[index(face)]; }
};

Components face_components(const TriangleMesh& mesh, const std::vector<double>& face_area) {
  Components components(mesh.triangles.size());
  std::unordered_map<uint64_t, int> first_face_on;
  first_face_on.reserve(2 * mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::ivec3& t = mesh.triangles[f];
    for (int c = 0; c < 3; ++c) {
      if (t[c] == t[(c + 1) % 3])
        continue;
      auto [it, inserted] = first_face_on.emplace(edge_key(t[c], t[(c + 1) % 3]), int(f));
      if (!inserted)
        components.face_sets.unite(it->second, int(f));
    }
  }
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    ComponentTopology& c = components.of(int(f));
    ++c.faces;
    c.area += face_area[f];
  }
  return components;
}

/// Vertices: one per (vertex, fan), with the components' bounds; pinched where a vertex has
/// several fans in one component. Returns the vertices with more than one fan in all.
size_t count_fan_vertices(const TriangleMesh& mesh, const Fans& fans, Components& components) {
  size_t pinched = 0;
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    std::map<size_t, int> fans_in_component;
    for (size_t k = 0; k < fans.vertex_faces[v].size(); ++k) {
      if (fans.fan_of[v][k] != int(k))
        continue;
      const size_t index = components.index(fans.vertex_faces[v][k]);
      ComponentTopology& c = components.list[index];
      ++c.vertices;
      c.bounds_min = glm::min(c.bounds_min, mesh.positions[v]);
      c.bounds_max = glm::max(c.bounds_max, mesh.positions[v]);
      ++fans_in_component[index];
    }
    size_t count = 0;
    for (const auto& [index, fans_here] : fans_in_component) {
      count += size_t(fans_here);
      components.list[index].non_manifold_vertices += fans_here > 1 ? 1 : 0;
    }
    pinched += count > 1 ? 1 : 0;
  }
  return pinched;
}

/// A boundary edge, directed as in its one face.
struct BoundaryEdge {
  int from, to, face;
};

/// Edge classes per component (each undirected edge counted once, in the component of its first
/// face: boundary, non-manifold, orientation); the boundary edges.
std::vector<BoundaryEdge> classify_edges(const TriangleMesh& mesh,
                                         std::unordered_map<uint64_t, EdgeUse>& edges,
                                         Components& components) {
  std::vector<BoundaryEdge> boundary;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::ivec3& t = mesh.triangles[f];
    if (has_repeated_corner(t))
      continue;
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      ComponentTopology& comp = components.of(int(f));
      EdgeUse& use = edges[edge_key(a, b)];
      if (!use.counted) {
        use.counted = true;
        ++comp.edges;
        if (use.faces == 1)
          ++comp.boundary_edges;
        else if (use.faces > 2)
          ++comp.non_manifold_edges;
        else if (use.low_to_high != 1)
          comp.oriented = false;
      }
      if (use.faces == 1)
        boundary.push_back({a, b, int(f)});
    }
  }
  return boundary;
}

/// Boundary loops per component: at each (vertex, fan) the incoming boundary edge continues
/// with the outgoing one.
void count_boundary_loops(const std::vector<BoundaryEdge>& boundary, const Fans& fans,
                          Components& components) {
  std::map<std::pair<int, int>, int> outgoing;  // (vertex, fan) -> boundary edge leaving it
  for (size_t e = 0; e < boundary.size(); ++e)
    outgoing[{boundary[e].from, fans.at(boundary[e].from, boundary[e].face)}] = int(e);
  UnionFind loops(boundary.size());
  for (size_t e = 0; e < boundary.size(); ++e) {
    const auto next = outgoing.find({boundary[e].to, fans.at(boundary[e].to, boundary[e].face)});
    if (next != outgoing.end())
      loops.unite(int(e), next->second);
  }
  for (size_t e = 0; e < boundary.size(); ++e)
    if (loops.find(int(e)) == int(e))
      ++components.of(boundary[e].face).boundary_loops;
}

/// Euler characteristic and genus of each component, the totals into `r`, largest first.
void finish_components(std::vector<ComponentTopology> components, TopologyReport& r) {
  for (ComponentTopology& c : components) {
    c.euler_characteristic = long(c.vertices) - long(c.edges) + long(c.faces);
    const long twice_genus = 2 - c.euler_characteristic - long(c.boundary_loops);
    c.genus = (c.non_manifold_edges == 0 && c.oriented && twice_genus >= 0 && twice_genus % 2 == 0)
                  ? twice_genus / 2
                  : -1;
    r.edges += c.edges;
    r.boundary_edges += c.boundary_edges;
    r.boundary_loops += c.boundary_loops;
    r.non_manifold_edges += c.non_manifold_edges;
    r.euler_characteristic += c.euler_characteristic;
  }
  std::stable_sort(
      components.begin(), components.end(),
      [](const ComponentTopology& a, const ComponentTopology& b) { return a.faces > b.faces; });
  r.components = std::move(components);
}

}  // namespace

TopologyReport analyze_topology(const TriangleMesh& mesh) {
  TopologyReport r;
  r.vertices = mesh.positions.size();
  r.faces = mesh.triangles.size();
  const std::vector<double> face_area = measure_faces(mesh, r);
  r.duplicate_positions = count_duplicate_positions(mesh);
  std::unordered_map<uint64_t, EdgeUse> edges = edge_uses(mesh);
  const Fans fans = vertex_fans(mesh);
  Components components = face_components(mesh, face_area);
  r.non_manifold_vertices = count_fan_vertices(mesh, fans, components);
  const std::vector<BoundaryEdge> boundary = classify_edges(mesh, edges, components);
  count_boundary_loops(boundary, fans, components);
  finish_components(std::move(components.list), r);
  return r;
}

}  // namespace gfield
