// Chart rasterisation at texel centres, orbifold tiling and dilation into the padding.

#include "preprocess/rasterize.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <set>
#include <tuple>

#include "gfield/check.hpp"

namespace gfield {
namespace {

ChartTransform compose(const ChartTransform& a, const ChartTransform& b) {  // a after b
  return {a.m * b.m, a.m * b.t + a.t};
}

ChartTransform rotation_about(glm::dvec2 centre, bool clockwise) {
  ChartTransform r;
  r.m = clockwise ? glm::dmat2(0.0, -1.0, 1.0, 0.0) : glm::dmat2(0.0, 1.0, -1.0, 0.0);
  r.t = centre - r.m * centre;
  return r;
}

double cross(glm::dvec2 a, glm::dvec2 b) {
  return a.x * b.y - a.y * b.x;
}

}  // namespace

std::vector<ChartTransform> orbifold_copies(glm::dvec2 lo, glm::dvec2 hi) {
  const ChartTransform generators[4] = {
      rotation_about({0.0, 0.0}, false), rotation_about({0.0, 0.0}, true),
      rotation_about({1.0, 1.0}, false), rotation_about({1.0, 1.0}, true)};
  auto key = [](const ChartTransform& g) {
    return std::make_tuple(std::lround(g.m[0][0]), std::lround(g.m[0][1]), std::lround(g.t.x * 1e6),
                           std::lround(g.t.y * 1e6));
  };
  auto meets_square = [&](const ChartTransform& g) {
    glm::dvec2 a(std::numeric_limits<double>::max()), b(-std::numeric_limits<double>::max());
    for (glm::dvec2 corner : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)}) {
      a = glm::min(a, g(corner));
      b = glm::max(b, g(corner));
    }
    return a.x < 1.0 && a.y < 1.0 && b.x > 0.0 && b.y > 0.0;
  };
  std::vector<ChartTransform> copies{ChartTransform{}};
  std::set<decltype(key(copies[0]))> seen{key(copies[0])};
  // Breadth-first over the group; copies that miss the square are not expanded (the tile is
  // connected and the copies meeting the square are reachable through copies meeting it).
  for (size_t next = 0; next < copies.size() && copies.size() < 64; ++next)
    for (const ChartTransform& generator : generators) {
      const ChartTransform g = compose(generator, copies[next]);
      if (!meets_square(g) || !seen.insert(key(g)).second)
        continue;
      copies.push_back(g);
    }
  return copies;
}

namespace {

/// Barycentric weights of point `c` in the triangle `q` of area `area` (twice the area).
glm::dvec3 barycentric(const glm::dvec2 q[3], glm::dvec2 c, double area) {
  return glm::dvec3(cross(q[1] - c, q[2] - c), cross(q[2] - c, q[0] - c),
                    cross(q[0] - c, q[1] - c)) /
         area;
}

/// What one triangle is rasterised from: the mesh, its normals, the albedo source (or null).
struct RasterSource {
  const TriangleMesh& mesh;
  const std::vector<glm::dvec3>& normals;
  const AlbedoSource* albedo;
};

/// Per texel: the smallest barycentric weight of the triangle that wrote it, and whether its
/// albedo is known (not a hole-filling face).
struct RasterState {
  std::vector<double> best;
  std::vector<char> albedo_known;
};

/// Writes the texels whose centres lie in face `face` (its image positions q, texels, counter-
/// clockwise) of the chart's `rect`, where it holds the centre more firmly than what is there.
void rasterize_triangle(const RasterSource& source, int face, const glm::dvec2 q[3],
                        const ChartRect& rect, GeometryImage& image, RasterState& state) {
  const double tolerance = 1e-6;
  const double area = cross(q[1] - q[0], q[2] - q[0]);
  if (!(area > 0.0))
    return;  // degenerate in uv: its neighbours cover its texels
  const glm::ivec3& t = source.mesh.triangles[size_t(face)];
  const glm::dvec2 lo = glm::min(q[0], glm::min(q[1], q[2]));
  const glm::dvec2 hi = glm::max(q[0], glm::max(q[1], q[2]));
  const int i0 = std::max(rect.x, int(std::ceil(lo.x - 0.5)));
  const int i1 = std::min(rect.x + rect.size - 1, int(std::floor(hi.x - 0.5)));
  const int j0 = std::max(rect.y, int(std::ceil(lo.y - 0.5)));
  const int j1 = std::min(rect.y + rect.size - 1, int(std::floor(hi.y - 0.5)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const glm::dvec2 c(i + 0.5, j + 0.5);
      glm::dvec3 w = barycentric(q, c, area);
      const double weakest = std::min(w.x, std::min(w.y, w.z));
      const size_t texel = size_t(j) * size_t(image.size) + size_t(i);
      if (weakest < -tolerance || weakest <= state.best[texel])
        continue;
      state.best[texel] = weakest;
      if (source.albedo != nullptr) {
        const glm::dvec3 di = barycentric(q, c + glm::dvec2(1.0, 0.0), area) - w;
        const glm::dvec3 dj = barycentric(q, c + glm::dvec2(0.0, 1.0), area) - w;
        state.albedo_known[texel] =
            source.albedo->sample(face, w, di, dj, image.albedo[texel]) ? 1 : 0;
      }
      w = glm::max(w, glm::dvec3(0.0));
      w /= w.x + w.y + w.z;
      const std::vector<glm::dvec3>& p = source.mesh.positions;
      const std::vector<glm::dvec3>& normals = source.normals;
      const glm::dvec3 n = w.x * normals[t[0]] + w.y * normals[t[1]] + w.z * normals[t[2]];
      const double length = glm::length(n);
      image.position[texel] = glm::vec3(w.x * p[t[0]] + w.y * p[t[1]] + w.z * p[t[2]]);
      image.normal[texel] = length > 0.0 ? glm::vec3(n / length) : glm::vec3(0, 0, 1);
      image.coverage[texel] = 1.0f;
    }
}

/// Covered texels whose albedo is unknown (faces that fill holes) take that of the nearest
/// known covered texel, breadth-first over covered 4-neighbours (mid-grey when none is known).
void fill_unknown_albedo(GeometryImage& image, std::vector<char>& known) {
  const int size = image.size;
  const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
  std::deque<size_t> queue;
  for (size_t texel = 0; texel < known.size(); ++texel)
    if (known[texel] && image.coverage[texel] > 0.0f)
      queue.push_back(texel);
  while (!queue.empty()) {
    const size_t texel = queue.front();
    queue.pop_front();
    const int i = int(texel % size_t(size)), j = int(texel / size_t(size));
    for (int k = 0; k < 4; ++k) {
      const int ni = i + di[k], nj = j + dj[k];
      const size_t neighbour = size_t(nj) * size_t(size) + size_t(ni);
      if (ni < 0 || nj < 0 || ni >= size || nj >= size || known[neighbour] ||
          !(image.coverage[neighbour] > 0.0f))
        continue;
      known[neighbour] = 1;
      image.albedo[neighbour] = image.albedo[texel];
      queue.push_back(neighbour);
    }
  }
  for (size_t texel = 0; texel < known.size(); ++texel)
    if (!known[texel] && image.coverage[texel] > 0.0f)
      image.albedo[texel] = glm::vec3(kMissingTextureGrey);
}

/// The chart's copies: itself, or the orbifold tiling's copies that meet the unit square.
std::vector<ChartTransform> chart_copies(const RasterChart& chart) {
  if (!chart.orbifold)
    return {ChartTransform{}};
  glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec2& uv : chart.corner_uv) {
    lo = glm::min(lo, uv);
    hi = glm::max(hi, uv);
  }
  return orbifold_copies(lo, hi);
}

/// Image uv of every corner of the chart's faces into face_uv (3 per face of the mesh): one copy
/// per face (orbifold: the copy holding the centroid).
void chart_corner_uvs(const RasterChart& chart, const std::vector<ChartTransform>& copies, int size,
                      std::vector<glm::vec2>& face_uv) {
  const ChartRect& rect = chart.rect;
  for (size_t local = 0; local < chart.faces.size(); ++local) {
    const glm::dvec2* uv = &chart.corner_uv[3 * local];
    const ChartTransform* chosen = &copies[0];
    const glm::dvec2 centroid = (uv[0] + uv[1] + uv[2]) / 3.0;
    for (const ChartTransform& g : copies) {
      const glm::dvec2 c = g(centroid);
      if (c.x >= 0.0 && c.x <= 1.0 && c.y >= 0.0 && c.y <= 1.0) {
        chosen = &g;
        break;
      }
    }
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 texels = glm::dvec2(rect.x, rect.y) + (*chosen)(uv[k]) * double(rect.size);
      face_uv[3 * size_t(chart.faces[local]) + k] = glm::vec2(texels / double(size));
    }
  }
}

/// The first ring around the charts extrapolates the surface linearly (2 p1 - p2 along each
/// direction with two covered texels, averaged, clamped to the box), so a bilinear lookup
/// between a chart's last texel centre and its edge follows the surface instead of stopping at
/// the last texel. Returns the ring's texels.
std::deque<size_t> extrapolate_first_ring(GeometryImage& image, const Box& box) {
  const int size = image.size;
  const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
  auto covered = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < size && j < size &&
           image.coverage[size_t(j) * size_t(size) + size_t(i)] > 0.0f;
  };
  std::deque<size_t> ring;
  for (size_t texel = 0; texel < image.coverage.size(); ++texel) {
    if (image.coverage[texel] > 0.0f)
      continue;
    const int i = int(texel % size_t(size)), j = int(texel / size_t(size));
    glm::vec3 position(0.0f), normal(0.0f);
    int extrapolated = 0, nearest = -1;
    for (int k = 0; k < 4; ++k) {
      const int i1 = i - di[k], j1 = j - dj[k];
      if (!covered(i1, j1))
        continue;
      const size_t t1 = size_t(j1) * size_t(size) + size_t(i1);
      if (nearest < 0)
        nearest = int(t1);
      if (!covered(i1 - di[k], j1 - dj[k]))
        continue;
      const size_t t2 = size_t(j1 - dj[k]) * size_t(size) + size_t(i1 - di[k]);
      position += 2.0f * image.position[t1] - image.position[t2];
      normal += 2.0f * image.normal[t1] - image.normal[t2];
      ++extrapolated;
    }
    if (nearest < 0)
      continue;
    if (extrapolated > 0 && glm::length(normal) > 0.0f) {
      image.position[texel] = glm::clamp(position / float(extrapolated), box.min, box.max);
      image.normal[texel] = glm::normalize(normal);
    } else {
      image.position[texel] = image.position[nearest];
      image.normal[texel] = image.normal[nearest];
    }
    if (!image.albedo.empty())
      image.albedo[texel] = image.albedo[size_t(nearest)];
    ring.push_back(texel);
  }
  return ring;
}

/// Padding: the first ring extrapolated, further texels the values of the nearest ring texel
/// (breadth-first over 4-neighbours, in texel order, so the result is deterministic).
void pad_image(GeometryImage& image, const Box& box) {
  const int size = image.size;
  const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
  std::vector<char> filled(image.coverage.size(), 0);
  for (size_t texel = 0; texel < filled.size(); ++texel)
    filled[texel] = image.coverage[texel] > 0.0f;
  std::deque<size_t> queue = extrapolate_first_ring(image, box);
  for (size_t texel : queue)
    filled[texel] = 1;
  while (!queue.empty()) {
    const size_t texel = queue.front();
    queue.pop_front();
    const int i = int(texel % size_t(size)), j = int(texel / size_t(size));
    for (int k = 0; k < 4; ++k) {
      const int ni = i + di[k], nj = j + dj[k];
      if (ni < 0 || nj < 0 || ni >= size || nj >= size)
        continue;
      const size_t neighbour = size_t(nj) * size_t(size) + size_t(ni);
      if (filled[neighbour])
        continue;
      filled[neighbour] = 1;
      image.position[neighbour] = image.position[texel];
      image.normal[neighbour] = image.normal[texel];
      if (!image.albedo.empty())
        image.albedo[neighbour] = image.albedo[texel];
      queue.push_back(neighbour);
    }
  }
}

}  // namespace

void rasterize_charts(const TriangleMesh& mesh, const std::vector<glm::dvec3>& normals,
                      const std::vector<RasterChart>& charts, int size, const Box& box,
                      const AlbedoSource* albedo, const SurfaceProjection* projection,
                      GeometryImage& image, std::vector<glm::vec2>& face_uv) {
  const size_t texels = size_t(size) * size_t(size);
  image.size = size;
  image.position.assign(texels, glm::vec3(0.0f));
  image.normal.assign(texels, glm::vec3(0.0f, 0.0f, 1.0f));
  image.coverage.assign(texels, 0.0f);
  image.albedo.assign(albedo != nullptr ? texels : 0, glm::vec3(0.0f));
  face_uv.assign(3 * mesh.triangles.size(), glm::vec2(0.0f));
  // Per texel, the smallest barycentric weight of the triangle that wrote it: the triangle that
  // holds the centre most firmly wins (ties: the first).
  RasterState state{std::vector<double>(texels, -std::numeric_limits<double>::infinity()),
                    std::vector<char>(albedo != nullptr ? texels : 0, 0)};
  const RasterSource source{mesh, normals, albedo};
  for (const RasterChart& chart : charts) {
    const ChartRect& rect = chart.rect;
    GF_CHECK(rect.x >= 0 && rect.y >= 0 && rect.size > 0, "a packed chart's rectangle");
    GF_CHECK_LE(std::max(rect.x, rect.y) + rect.size, size, "a packed chart inside the image");
    GF_CHECK_EQ(chart.corner_uv.size(), 3 * chart.faces.size(), "a uv per corner of its faces");
    const std::vector<ChartTransform> copies = chart_copies(chart);
    auto to_texels = [&](glm::dvec2 uv) {
      return glm::dvec2(rect.x, rect.y) + uv * double(rect.size);
    };
    for (const ChartTransform& g : copies) {
      for (size_t local = 0; local < chart.faces.size(); ++local) {
        const glm::dvec2 q[3] = {to_texels(g(chart.corner_uv[3 * local])),
                                 to_texels(g(chart.corner_uv[3 * local + 1])),
                                 to_texels(g(chart.corner_uv[3 * local + 2]))};
        rasterize_triangle(source, chart.faces[local], q, rect, image, state);
      }
    }
    chart_corner_uvs(chart, copies, size, face_uv);
  }
  if (albedo != nullptr)
    fill_unknown_albedo(image, state.albedo_known);
  if (projection != nullptr)
    projection->project(image);
  pad_image(image, box);
}

}  // namespace gfield
