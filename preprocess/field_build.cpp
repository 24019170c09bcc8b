#include "preprocess/field_build.hpp"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

#include "gfield/stopwatch.hpp"
#include "preprocess/field_casts.hpp"

namespace gfield {
namespace {

/// Hits looked for per line at most (kAutoLayers: one more than can be stored, to count the
/// lines with more hits than layers).
constexpr int kMaxCollected = kMaxFieldLayers + 1;

/// Hits collected per line from its entry when each ray needs `capacity`: 2 capacity + 1, so that
/// a line holding up to 2 capacity hits is complete (its entry ray's first `capacity` hits and
/// its exit ray's are all among them) and needs no traversal from its exit. Measured for K = 2
/// (`bench_field_build`, spot / homer / bunny, build over the bare first-hit cast): 3 hits per
/// line 1.49 / 1.46 / 1.43, 4 hits 1.56 / 1.56 / 1.52, 5 hits 1.39 / 1.42 / 1.42, 7 hits 1.41 /
/// 1.43 / 1.50: lines of two parts (4 hits) are common, and a second traversal costs more than
/// a longer first one.
int line_capacity(int capacity) {
  return std::min(kMaxHitList, 2 * capacity + 1);
}

/// Rays by number of hits found (FieldBuildStats::lines_by_hits).
using Histogram = std::array<size_t, kMaxFieldLayers + 2>;

/// A value per thread, found through a thread-local key (local() is called once per packet).
template <class T>
using PerThread =
    tbb::enumerable_thread_specific<T, tbb::cache_aligned_allocator<T>, tbb::ets_key_per_instance>;

/// The bilinear patch of an n^2 image under `uv`: its lower-left texel; x = uv in texel-centre
/// coordinates, clamped to the grid.
glm::ivec2 patch_under(int n, glm::vec2 uv, glm::vec2& x) {
  for (int a = 0; a < 2; ++a) {  // a NaN uv (float barycentrics underflowed) reads patch 0
    x[a] = std::isnan(uv[a]) ? 0.0f : std::clamp(uv[a] * float(n) - 0.5f, 0.0f, float(n - 1));
  }
  return glm::clamp(glm::ivec2(glm::floor(x)), glm::ivec2(0), glm::ivec2(n - 2));
}

/// True when the bilinear patch under `uv` has all 4 texels covered (`patches`:
/// covered_patches(image)).
bool in_covered_patch(const GeometryImage& image, const std::vector<uint8_t>& patches,
                      glm::vec2 uv) {
  glm::vec2 x;
  const glm::ivec2 c = patch_under(image.size, uv, x);
  return patches[size_t(c.y) * size_t(image.size - 1) + size_t(c.x)] != 0;
}

/// Per triangle of the parameterised mesh (`corner_uv`: 3 per triangle), 1 when every bilinear
/// patch under its uv footprint has all 4 texels covered, so that no hit on it needs
/// snap_to_covered: the patches of the bounding box of its corners' uvs (clamped to [0,1]^2 as
/// hit_uv clamps them), widened by 10^-3 texel against rounding in the interpolation.
std::vector<uint8_t> triangles_in_covered_patches(const GeometryImage& image,
                                                  const std::vector<uint8_t>& patches,
                                                  const std::vector<glm::vec2>& corner_uv) {
  const int n = image.size;
  std::vector<uint8_t> inside(corner_uv.size() / 3);
  for (size_t t = 0; t < inside.size(); ++t) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (size_t c = 0; c < 3; ++c) {
      const glm::vec2 x = glm::clamp(corner_uv[3 * t + c], 0.0f, 1.0f) * float(n) - 0.5f;
      lo = glm::min(lo, x);
      hi = glm::max(hi, x);
    }
    const glm::ivec2 first = glm::clamp(glm::ivec2(glm::floor(lo - 1e-3f)), 0, n - 2);
    const glm::ivec2 last = glm::clamp(glm::ivec2(glm::floor(hi + 1e-3f)), 0, n - 2);
    bool covered = true;
    for (int j = first.y; j <= last.y && covered; ++j) {
      for (int i = first.x; i <= last.x && covered; ++i) {
        covered = patches[size_t(j) * size_t(n - 1) + size_t(i)] != 0;
      }
    }
    inside[t] = uint8_t(covered);
  }
  return inside;
}

/// Writes the hits of the casts into the layers of the table.
struct TableWriter {
  const GeometryImage& image;
  std::vector<uint8_t> patches;   ///< covered_patches(image)
  const glm::vec2* corner_uv;     ///< 3 per triangle of the parameterised mesh
  std::vector<uint8_t> inside;    ///< triangles_in_covered_patches(image, patches, corner uvs)
  std::vector<glm::vec3> points;  ///< sample_points(box, n)
  int n;
  int stored;    ///< layers written
  int capacity;  ///< hits looked for per ray
  glm::vec2* table;

  glm::vec2& at(int layer, int entry, int exit) const {
    const size_t side = points.size();
    return table[(size_t(layer) * side + size_t(entry)) * side + size_t(exit)];
  }

  /// The uv of hit `k` of `list` on the ray from `from` to `to`: the hit triangle's corner uvs
  /// interpolated with the barycentrics, clamped to [0,1]^2 (corner uvs of faces across the
  /// image border, orbifold copies, may leave it a little, as GL_CLAMP_TO_EDGE would), snapped
  /// to a covered patch.
  glm::vec2 hit_uv(const HitList& list, int k, int from, int to) const {
    const unsigned triangle = list.triangle[size_t(k)];
    const glm::vec2* uv = corner_uv + 3 * size_t(triangle);
    const glm::vec2 b = list.barycentric[size_t(k)];
    const glm::vec2 value =
        glm::clamp((1.0f - b.x - b.y) * uv[0] + b.x * uv[1] + b.y * uv[2], 0.0f, 1.0f);
    if (inside[triangle] != 0 || in_covered_patch(image, patches, value)) {
      return value;
    }
    const glm::vec3 origin = points[size_t(from)];
    const glm::vec3 hit = origin + list.t[size_t(k)] * (points[size_t(to)] - origin);
    return snap_to_covered(image, patches, value, hit);
  }

  /// K = 1: stores the first hits of the rays from `entry` to exits first..first+7 (past the
  /// row's end: none) and counts them into `histogram` by hits found.
  void store_first(int entry, int first, const std::array<HitList, 8>& lanes, bool cast,
                   Histogram& histogram) const {
    const int per_face = n * n;
    const int valid_lanes = std::min(8, int(points.size()) - first);
    for (int lane = 0; lane < valid_lanes; ++lane) {
      const int exit = first + lane;
      const bool ray = cast && exit / per_face != entry / per_face;
      const bool hit = ray && lanes[size_t(lane)].count > 0;
      histogram[size_t(hit)] += size_t(ray);
      at(0, entry, exit) = hit ? hit_uv(lanes[size_t(lane)], 0, entry, exit)
                               : glm::vec2(ray ? kFieldMiss : kFieldNoRay);
    }
  }

  /// K > 1: stores the `count` lines entry -> first.., both their rays, and counts the rays into
  /// `histogram` by hits found.
  void store_lines(int entry, int first, int count, const std::array<LineHits, 8>& lines,
                   Histogram& histogram) const {
    for (int lane = 0; lane < count; ++lane) {
      const LineHits& line = lines[size_t(lane)];
      const int exit = first + lane;
      if (!line.ray) {
        for (int layer = 0; layer < stored; ++layer) {
          at(layer, entry, exit) = at(layer, exit, entry) = glm::vec2(kFieldNoRay);
        }
      } else if (line.complete) {
        store_line(entry, exit, line.hits, histogram);
      } else {
        store_ray(entry, exit, line.hits);
        store_ray(exit, entry, line.reverse);
        histogram[size_t(capacity)] += 2;  // a full list: at least `capacity` hits each way
      }
    }
  }

  /// The line entry <-> exit whose hits are all in `list` (t along entry -> exit): each hit's uv
  /// once, into the layers of both rays.
  void store_line(int entry, int exit, const HitList& list, Histogram& histogram) const {
    const int count = list.count;
    std::array<glm::vec2, kMaxHitList> uv;
    for (int k = 0; k < count; ++k) {
      if (k < stored || k >= count - stored) {
        uv[size_t(k)] = hit_uv(list, k, entry, exit);
      }
    }
    for (int layer = 0; layer < stored; ++layer) {
      const bool hit = layer < count;
      at(layer, entry, exit) = hit ? uv[size_t(layer)] : glm::vec2(kFieldMiss);
      at(layer, exit, entry) = hit ? uv[size_t(count - 1 - layer)] : glm::vec2(kFieldMiss);
    }
    histogram[size_t(std::min(count, capacity))] += 2;
  }

  /// The ray from -> to whose nearest hits are `list` (t along from -> to; more may follow).
  void store_ray(int from, int to, const HitList& list) const {
    for (int layer = 0; layer < stored; ++layer) {
      at(layer, from, to) =
          layer < list.count ? hit_uv(list, layer, from, to) : glm::vec2(kFieldMiss);
    }
  }
};

/// K for kAutoLayers: the smallest whose layers hold every hit of kLayerCoverage of the lines.
int choose_layers(const FieldBuildStats& stats) {
  for (int k = 1; k < kMaxFieldLayers; ++k) {
    if (layer_coverage(stats, k) >= kLayerCoverage) {
      return k;
    }
  }
  return kMaxFieldLayers;
}

}  // namespace

size_t field_memory_estimate(int samples_per_side, int layers, bool half_precision) {
  const size_t side = size_t(sample_count(samples_per_side));
  const size_t stored = size_t(layers == kAutoLayers ? kMaxFieldLayers : layers);
  return side * side * stored * (sizeof(glm::vec2) + (half_precision ? 4 : 8));
}

double layer_coverage(const FieldBuildStats& stats, int layers) {
  if (stats.collected <= layers || stats.rays == 0) {
    return -1.0;
  }
  size_t held = 0;
  for (int h = 0; h <= layers; ++h) {
    held += stats.lines_by_hits[size_t(h)];
  }
  return double(held) / double(stats.rays);
}

size_t available_memory() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  size_t value = 0;
  std::string unit;
  while (meminfo >> key >> value >> unit) {
    if (key == "MemAvailable:") {
      return value * 1024;
    }
  }
  return 0;
}

bool check_field_size(int samples_per_side, int layers, bool half_precision, std::string& error) {
  if (samples_per_side < kMinSamplesPerSide || samples_per_side > kMaxSamplesPerSide) {
    error = "samples per side " + std::to_string(samples_per_side) + " out of range [" +
            std::to_string(kMinSamplesPerSide) + ", " + std::to_string(kMaxSamplesPerSide) + "]";
    return false;
  }
  if (layers < kAutoLayers || layers > kMaxFieldLayers) {
    error = "layers " + std::to_string(layers) + " out of range [1, " +
            std::to_string(kMaxFieldLayers) + "]";
    return false;
  }
  const size_t needed = field_memory_estimate(samples_per_side, layers, half_precision);
  const size_t available = available_memory();
  if (available != 0 && needed > available) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "a field with N = %d and %d layers needs about %.0f MB but only %.0f MB of "
                  "memory is available",
                  samples_per_side, layers == kAutoLayers ? kMaxFieldLayers : layers,
                  double(needed) / 1e6, double(available) / 1e6);
    error = text;
    return false;
  }
  return true;
}

std::vector<uint8_t> covered_patches(const GeometryImage& image) {
  const int n = image.size;
  std::vector<uint8_t> covered(size_t(n - 1) * size_t(n - 1));
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      covered[size_t(j) * size_t(n - 1) + size_t(i)] =
          image.coverage[texel_index(image, i, j)] > 0.0f &&
          image.coverage[texel_index(image, i + 1, j)] > 0.0f &&
          image.coverage[texel_index(image, i, j + 1)] > 0.0f &&
          image.coverage[texel_index(image, i + 1, j + 1)] > 0.0f;
    }
  }
  return covered;
}

glm::vec2 snap_to_covered(const GeometryImage& image, const std::vector<uint8_t>& patches,
                          glm::vec2 uv, glm::vec3 hit) {
  const int n = image.size;
  const auto covered = [&](int i, int j) {
    return patches[size_t(j) * size_t(n - 1) + size_t(i)] != 0;
  };
  glm::vec2 x;
  const glm::ivec2 c = patch_under(n, uv, x);
  if (covered(c.x, c.y)) {
    return uv;
  }
  glm::vec2 best = uv;
  const glm::vec3 d0 = sample_position(image, uv) - hit;
  float best_distance = glm::dot(d0, d0);  // squared
  for (int j = std::max(0, c.y - 2); j <= std::min(n - 2, c.y + 2); ++j) {
    for (int i = std::max(0, c.x - 2); i <= std::min(n - 2, c.x + 2); ++i) {
      if (!covered(i, j)) {
        continue;
      }
      const glm::vec2 f = glm::clamp(x - glm::vec2(i, j), 0.0f, 1.0f);
      const glm::vec3 a = glm::mix(image.position[texel_index(image, i, j)],
                                   image.position[texel_index(image, i + 1, j)], f.x);
      const glm::vec3 b = glm::mix(image.position[texel_index(image, i, j + 1)],
                                   image.position[texel_index(image, i + 1, j + 1)], f.x);
      const glm::vec3 d = glm::mix(a, b, f.y) - hit;
      if (glm::dot(d, d) < best_distance) {
        best_distance = glm::dot(d, d);
        best = (glm::vec2(i, j) + f + 0.5f) / float(n);
      }
    }
  }
  return best;
}

bool build_geometry_field(const ParameterizedMesh& pm, const EmbreeMesh& embree,
                          const GeometryImage& image, int samples_per_side, int layers,
                          GeometryField& field, std::string& error, FieldBuildStats* stats,
                          const JobControl* control) {
  Stopwatch watch;
  if (image.size < 2 || image.coverage.size() != size_t(image.size) * size_t(image.size) ||
      image.position.size() != image.coverage.size()) {
    error = "the geometry image is empty or inconsistent";
    return false;
  }
  const int n = samples_per_side;
  if (n < kMinSamplesPerSide || n > kMaxSamplesPerSide || layers < kAutoLayers ||
      layers > kMaxFieldLayers) {
    error = "samples per side " + std::to_string(n) + " or layers " + std::to_string(layers) +
            " out of range [" + std::to_string(kMinSamplesPerSide) + ", " +
            std::to_string(kMaxSamplesPerSide) + "], [1, " + std::to_string(kMaxFieldLayers) + "]";
    return false;
  }
  if (pm.corner_uv.size() != 3 * pm.mesh.triangles.size()) {
    error = "the parameterized mesh has " + std::to_string(pm.corner_uv.size()) +
            " corner uvs for " + std::to_string(pm.mesh.triangles.size()) + " triangles";
    return false;
  }
  const size_t side = size_t(sample_count(n));
  const size_t count = side * side;
  const int stored = layers == kAutoLayers ? kMaxFieldLayers : layers;
  const int capacity = layers == kAutoLayers ? kMaxCollected : layers;
  field.samples_per_side = n;
  field.layers = stored;
  field.box = image.box;
  field.uv.clear();  // a field built before keeps its memory, but its values are not copied
  field.uv.resize(count * size_t(stored));  // every entry is written below, row by row

  std::vector<uint8_t> patches = covered_patches(image);
  std::vector<uint8_t> inside = triangles_in_covered_patches(image, patches, pm.corner_uv);
  const TableWriter writer{.image = image,
                           .patches = std::move(patches),
                           .corner_uv = pm.corner_uv.data(),
                           .inside = std::move(inside),
                           .points = sample_points(image.box, n),
                           .n = n,
                           .stored = stored,
                           .capacity = capacity,
                           .table = field.uv.data()};
  PerThread<Histogram> histograms(Histogram{});
  if (capacity == 1) {
    cast_first_hits(
        embree, writer.points, n,
        [&](int entry, int first, const std::array<HitList, 8>& lanes, bool cast) {
          writer.store_first(entry, first, lanes, cast, histograms.local());
        },
        control);
  } else {
    cast_lines(
        embree, writer.points, n, line_capacity(capacity), stored,
        [&](int entry, int first, int count, const std::array<LineHits, 8>& lines) {
          writer.store_lines(entry, first, count, lines, histograms.local());
        },
        control);
  }
  if (stop_requested(control)) {
    error = kInterrupted;
    return false;
  }
  report_progress(control, "field", 1.0);

  FieldBuildStats s;
  s.rays = count - 6 * size_t(n * n) * size_t(n * n);
  s.collected = capacity;
  s.lines_by_hits = histograms.combine([](const Histogram& a, const Histogram& b) {
    Histogram sum;
    for (size_t h = 0; h < sum.size(); ++h) {
      sum[h] = a[h] + b[h];
    }
    return sum;
  });
  s.hits = s.rays - s.lines_by_hits[0];
  s.layers = layers == kAutoLayers ? choose_layers(s) : layers;
  field.layers = s.layers;
  field.uv.resize(count * size_t(s.layers));
  field.uv.shrink_to_fit();  // the layers beyond the chosen K
  s.seconds = watch.seconds();
  if (stats != nullptr) {
    *stats = s;
  }
  return true;
}

size_t cast_field_rays(const EmbreeMesh& embree, const Box& box, int samples_per_side, int layers) {
  const std::vector<glm::vec3> points = sample_points(box, samples_per_side);
  PerThread<size_t> hits(size_t(0));
  if (layers <= 1) {
    cast_first_hits(embree, points, samples_per_side,
                    [&](int, int, const std::array<HitList, 8>& lanes, bool) {
                      for (const HitList& list : lanes) {
                        hits.local() += size_t(list.count > 0);
                      }
                    });
  } else {
    const int capacity = std::min(layers, kMaxCollected);
    cast_lines(embree, points, samples_per_side, line_capacity(capacity),
               std::min(capacity, kMaxFieldLayers),
               [&](int, int, int count, const std::array<LineHits, 8>& lines) {
                 for (int lane = 0; lane < count; ++lane) {
                   const LineHits& line = lines[size_t(lane)];
                   const HitList& back = line.complete ? line.hits : line.reverse;
                   hits.local() += size_t(line.hits.count > 0) + size_t(back.count > 0);
                 }
               });
  }
  return hits.combine([](size_t a, size_t b) { return a + b; });
}

}  // namespace gfield
