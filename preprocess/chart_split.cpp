// Compressed regions of a chart -> face groups to chart separately.

#include "preprocess/chart_split.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "geometry/edge_key.hpp"

namespace gfield {
namespace {

/// Edge-connected components of the faces with `member[f]`; their face lists.
std::vector<std::vector<int>> face_regions(const std::vector<glm::ivec3>& neighbours,
                                           const std::vector<char>& member) {
  std::vector<std::vector<int>> regions;
  std::vector<char> seen(member.size(), 0);
  for (size_t start = 0; start < member.size(); ++start) {
    if (!member[start] || seen[start])
      continue;
    regions.emplace_back();
    std::vector<int> stack{int(start)};
    seen[start] = 1;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      regions.back().push_back(f);
      for (int k = 0; k < 3; ++k) {
        const int g = neighbours[f][k];
        if (g >= 0 && member[g] && !seen[g]) {
          seen[g] = 1;
          stack.push_back(g);
        }
      }
    }
    std::sort(regions.back().begin(), regions.back().end());
  }
  return regions;
}

/// Face neighbours across edges (-1 on the boundary): F x 3, neighbour k across edge k -> k+1.
std::vector<glm::ivec3> face_neighbours(const TriangleMesh& mesh) {
  const size_t nf = mesh.triangles.size();
  std::vector<glm::ivec3> neighbours(nf, glm::ivec3(-1));
  std::unordered_map<uint64_t, int> directed;
  directed.reserve(3 * nf);
  for (size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const glm::ivec3& t = mesh.triangles[f];
      directed[half_edge_key(t[k], t[(k + 1) % 3])] = int(f);
    }
  for (size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const glm::ivec3& t = mesh.triangles[f];
      auto it = directed.find(half_edge_key(t[(k + 1) % 3], t[k]));
      if (it != directed.end())
        neighbours[f][k] = it->second;
    }
  return neighbours;
}

/// Faces whose uv area share is below options.threshold times their surface area share, grown
/// by options.grow_rings rings of neighbours; `area` gets the F surface areas. Empty when the
/// surface or its uvs have no area.
std::vector<char> compressed_faces(const TriangleMesh& mesh,
                                   const std::vector<glm::dvec2>& corner_uv,
                                   const std::vector<glm::ivec3>& neighbours,
                                   const SplitOptions& options, std::vector<double>& area) {
  const size_t nf = mesh.triangles.size();
  area.assign(nf, 0.0);
  std::vector<double> uv_area(nf);
  double total = 0.0, uv_total = 0.0;
  for (size_t f = 0; f < nf; ++f) {
    const glm::ivec3& t = mesh.triangles[f];
    area[f] = 0.5 * glm::length(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                           mesh.positions[t[2]] - mesh.positions[t[0]]));
    const glm::dvec2 a = corner_uv[3 * f], b = corner_uv[3 * f + 1], c = corner_uv[3 * f + 2];
    uv_area[f] = 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    total += area[f];
    uv_total += uv_area[f];
  }
  if (!(total > 0.0) || !(uv_total > 0.0))
    return {};
  std::vector<char> marked(nf, 0);
  for (size_t f = 0; f < nf; ++f)
    marked[f] = area[f] > 0.0 && (uv_area[f] / uv_total) < options.threshold * (area[f] / total);
  for (int ring = 0; ring < options.grow_rings; ++ring) {
    std::vector<char> grown = marked;
    for (size_t f = 0; f < nf; ++f)
      if (marked[f])
        for (int k = 0; k < 3; ++k)
          if (neighbours[f][k] >= 0)
            grown[neighbours[f][k]] = 1;
    marked.swap(grown);
  }
  return marked;
}

double region_area(const std::vector<int>& faces, const std::vector<double>& area) {
  double sum = 0.0;
  for (int f : faces)
    sum += area[f];
  return sum;
}

}  // namespace

std::vector<std::vector<int>> split_compressed_regions(const TriangleMesh& mesh,
                                                       const std::vector<glm::dvec2>& corner_uv,
                                                       const SplitOptions& options) {
  const size_t nf = mesh.triangles.size();
  const std::vector<glm::ivec3> neighbours = face_neighbours(mesh);
  std::vector<double> area;
  std::vector<char> marked = compressed_faces(mesh, corner_uv, neighbours, options, area);
  if (marked.empty())
    return {};
  double total = 0.0;
  for (double a : area)
    total += a;
  // Keep the large compressed regions only.
  bool any = false;
  for (const std::vector<int>& region : face_regions(neighbours, marked)) {
    const bool keep = region_area(region, area) >= options.min_area_fraction * total;
    any |= keep;
    if (!keep)
      for (int f : region)
        marked[f] = 0;
  }
  if (!any)
    return {};
  // The largest uncompressed region is the rest; smaller ones enclosed by regions join them.
  std::vector<char> unmarked(nf);
  for (size_t f = 0; f < nf; ++f)
    unmarked[f] = !marked[f];
  std::vector<std::vector<int>> rest_regions = face_regions(neighbours, unmarked);
  if (rest_regions.empty())
    return {};
  size_t largest = 0;
  for (size_t r = 1; r < rest_regions.size(); ++r)
    if (region_area(rest_regions[r], area) > region_area(rest_regions[largest], area))
      largest = r;
  for (size_t r = 0; r < rest_regions.size(); ++r)
    if (r != largest)
      for (int f : rest_regions[r])
        marked[f] = 1;
  std::vector<std::vector<int>> groups{rest_regions[largest]};
  for (std::vector<int>& region : face_regions(neighbours, marked))
    groups.push_back(std::move(region));
  if (groups.size() < 2)
    return {};
  return groups;
}

}  // namespace gfield
