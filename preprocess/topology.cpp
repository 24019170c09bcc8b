#include "preprocess/topology.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>

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

/// Every edge's faces: each side of a face (corners a != b) filed under its lower vertex, sorted
/// by the higher one, so that an undirected edge is a run of equal `high` within its vertex's
/// range halves[first[v], first[v + 1]). Faces with a repeated corner contribute their proper
/// sides.
struct EdgeTable {
  struct Side {
    int high = 0, face = 0;
    bool low_to_high = false;  ///< the face runs along it from the lower index to the higher
    bool operator<(const Side& o) const { return high != o.high ? high < o.high : face < o.face; }
  };
  std::vector<size_t> first;  ///< V + 1 offsets
  std::vector<Side> sides;

  /// Calls `edge(low, begin, end)` for each undirected edge, [begin, end) its sides.
  template <typename F>
  void for_each_edge(F&& edge) const {
    for (size_t v = 0; v + 1 < first.size(); ++v)
      for (size_t run = first[v]; run < first[v + 1];) {
        size_t stop = run + 1;
        while (stop < first[v + 1] && sides[stop].high == sides[run].high)
          ++stop;
        edge(int(v), run, stop);
        run = stop;
      }
  }
};

EdgeTable edge_table(const TriangleMesh& mesh) {
  EdgeTable table;
  table.first.assign(mesh.positions.size() + 1, 0);
  for (const glm::ivec3& t : mesh.triangles)
    for (int c = 0; c < 3; ++c)
      if (t[c] != t[(c + 1) % 3])
        ++table.first[size_t(std::min(t[c], t[(c + 1) % 3])) + 1];
  std::partial_sum(table.first.begin(), table.first.end(), table.first.begin());
  table.sides.resize(table.first.back());
  std::vector<size_t> next(table.first.begin(), table.first.end() - 1);
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::ivec3& t = mesh.triangles[f];
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      if (a != b)
        table.sides[next[size_t(std::min(a, b))]++] = {std::max(a, b), int(f), a < b};
    }
  }
  for (size_t v = 0; v + 1 < table.first.size(); ++v)
    std::sort(table.sides.begin() + std::ptrdiff_t(table.first[v]),
              table.sides.begin() + std::ptrdiff_t(table.first[v + 1]));
  return table;
}

/// Fans: around each vertex, faces linked through the edges they share at that vertex. A vertex
/// with more than one fan is pinched (non-manifold) and counts once per fan, i.e. the surface is
/// analysed as if pinched vertices were split. faces[first[v], first[v + 1]) are the faces
/// around v in increasing order, fan[] at the same places their fans (a local index: the
/// smallest local index of the fan's faces).
struct Fans {
  std::vector<size_t> first;  ///< V + 1 offsets
  std::vector<int> faces;
  std::vector<int> fan;
  /// The fan of face f around vertex v.
  int at(int v, int f) const {
    const auto begin = faces.begin() + std::ptrdiff_t(first[size_t(v)]);
    const auto end = faces.begin() + std::ptrdiff_t(first[size_t(v) + 1]);
    return fan[size_t(std::lower_bound(begin, end, f) - faces.begin())];
  }
};

Fans vertex_fans(const TriangleMesh& mesh) {
  Fans fans;
  fans.first.assign(mesh.positions.size() + 1, 0);
  for (const glm::ivec3& t : mesh.triangles)
    if (!has_repeated_corner(t))
      for (int c = 0; c < 3; ++c)
        ++fans.first[size_t(t[c]) + 1];
  std::partial_sum(fans.first.begin(), fans.first.end(), fans.first.begin());
  fans.faces.resize(fans.first.back());
  fans.fan.resize(fans.first.back());
  std::vector<size_t> next(fans.first.begin(), fans.first.end() - 1);
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::ivec3& t = mesh.triangles[f];
    if (!has_repeated_corner(t))
      for (int c = 0; c < 3; ++c)
        fans.faces[next[size_t(t[c])]++] = int(f);
  }
  UnionFind fan(0);
  std::vector<std::pair<int, int>> corners;  // (other corner, local face index), sorted
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const size_t begin = fans.first[v], count = fans.first[v + 1] - begin;
    fan.parent.resize(count);
    std::iota(fan.parent.begin(), fan.parent.end(), 0);
    corners.clear();
    for (size_t k = 0; k < count; ++k) {
      const glm::ivec3& t = mesh.triangles[size_t(fans.faces[begin + k])];
      for (int c = 0; c < 3; ++c)
        if (t[c] != int(v))
          corners.emplace_back(t[c], int(k));
    }
    std::sort(corners.begin(), corners.end());
    for (size_t i = 1; i < corners.size(); ++i)  // faces sharing an edge at v share a fan
      if (corners[i].first == corners[i - 1].first)
        fan.unite(corners[i - 1].second, corners[i].second);
    for (size_t k = 0; k < count; ++k)
      fans.fan[begin + k] = fan.find(int(k));
  }
  return fans;
}

/// Components: faces connected through shared edges, with their faces and area counted.
struct Components {
  UnionFind face_sets;
  std::vector<int> index_of_root;  ///< F: a root face's index in `list`, or -1
  std::vector<ComponentTopology> list;

  explicit Components(size_t faces) : face_sets(faces), index_of_root(faces, -1) {}
  /// Index in `list` of the component of `face` (made on first use).
  size_t index(int face) {
    int& index = index_of_root[size_t(face_sets.find(face))];
    if (index < 0) {
      index = int(list.size());
      list.emplace_back();
      list.back().bounds_min = glm::dvec3(std::numeric_limits<double>::max());
      list.back().bounds_max = glm::dvec3(std::numeric_limits<double>::lowest());
    }
    return size_t(index);
  }
  ComponentTopology& of(int face) { return list[index(face)]; }
};

Components face_components(const TriangleMesh& mesh, const EdgeTable& edges,
                           const std::vector<double>& face_area) {
  Components components(mesh.triangles.size());
  edges.for_each_edge([&](int, size_t begin, size_t end) {
    for (size_t k = begin + 1; k < end; ++k)
      components.face_sets.unite(edges.sides[begin].face, edges.sides[k].face);
  });
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
  std::vector<size_t> fan_components;  // the component of each fan at a vertex, sorted
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    fan_components.clear();
    for (size_t k = 0; k < fans.first[v + 1] - fans.first[v]; ++k) {
      if (fans.fan[fans.first[v] + k] != int(k))
        continue;
      const size_t index = components.index(fans.faces[fans.first[v] + k]);
      ComponentTopology& c = components.list[index];
      ++c.vertices;
      c.bounds_min = glm::min(c.bounds_min, mesh.positions[v]);
      c.bounds_max = glm::max(c.bounds_max, mesh.positions[v]);
      fan_components.push_back(index);
    }
    std::sort(fan_components.begin(), fan_components.end());
    for (size_t k = 1; k < fan_components.size(); ++k)
      if (fan_components[k] == fan_components[k - 1] &&
          (k == 1 || fan_components[k - 2] != fan_components[k]))
        ++components.list[fan_components[k]].non_manifold_vertices;
    pinched += fan_components.size() > 1 ? 1 : 0;
  }
  return pinched;
}

/// A boundary edge, directed as in its one face; `side` is its place in that face (0-2).
struct BoundaryEdge {
  int from, to, face, side;
};

/// Edge classes per component (each undirected edge of a face without a repeated corner counted
/// once: boundary, non-manifold, orientation); the boundary edges in face order.
std::vector<BoundaryEdge> classify_edges(const TriangleMesh& mesh, const EdgeTable& edges,
                                         Components& components) {
  std::vector<BoundaryEdge> boundary;
  edges.for_each_edge([&](int low, size_t begin, size_t end) {
    int proper_face = -1, low_to_high = 0;
    for (size_t k = begin; k < end; ++k) {
      const EdgeTable::Side& side = edges.sides[k];
      low_to_high += side.low_to_high ? 1 : 0;
      if (proper_face < 0 && !has_repeated_corner(mesh.triangles[size_t(side.face)]))
        proper_face = side.face;
    }
    if (proper_face < 0)
      return;
    ComponentTopology& comp = components.of(proper_face);
    const size_t faces = end - begin;
    ++comp.edges;
    if (faces == 1) {
      ++comp.boundary_edges;
      const EdgeTable::Side& side = edges.sides[begin];
      const int from = side.low_to_high ? low : side.high, to = side.low_to_high ? side.high : low;
      const glm::ivec3& t = mesh.triangles[size_t(side.face)];
      const int place = t[0] == from ? 0 : t[1] == from ? 1 : 2;
      boundary.push_back({from, to, side.face, place});
    } else if (faces > 2) {
      ++comp.non_manifold_edges;
    } else if (low_to_high != 1) {
      comp.oriented = false;
    }
  });
  std::sort(boundary.begin(), boundary.end(), [](const BoundaryEdge& a, const BoundaryEdge& b) {
    return a.face != b.face ? a.face < b.face : a.side < b.side;
  });
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
  const EdgeTable edges = edge_table(mesh);
  const Fans fans = vertex_fans(mesh);
  Components components = face_components(mesh, edges, face_area);
  r.non_manifold_vertices = count_fan_vertices(mesh, fans, components);
  const std::vector<BoundaryEdge> boundary = classify_edges(mesh, edges, components);
  count_boundary_loops(boundary, fans, components);
  finish_components(std::move(components.list), r);
  return r;
}

}  // namespace gfield
