#include "preprocess/field_build.hpp"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <vector>

#include "gfield/check.hpp"
#include "gfield/field_lines.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/field_casts.hpp"

namespace gfield {
namespace {

/// Hits collected per line from its lower sample: a line of fewer is complete in one traversal
/// (lines of two solid parts, 4 hits, are common; a second traversal costs more than a longer
/// first one). A line that fills the list is traversed again from its higher sample for the
/// kEndHits nearest there: with the list's first kEndHits they are all its hits when it holds
/// kMaxLineHits, and its 4 nearest each end when it holds more.
constexpr int kLineCapacity = kMaxLineHits;
constexpr int kEndHits = kMaxLineHits / 2;

/// Rays by number of hits found (FieldBuildStats::lines_by_hits).
using Histogram = std::array<size_t, kMaxLineHits + 2>;

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

/// The hits of a line: all of a complete one; kMaxLineHits when the traversal from its higher
/// sample meets the list's last kEndHits (its kEndHits-th hit there is the list's next), more
/// (kMaxLineHits + 1) when they part.
int hit_count(const LineCast& line) {
  if (line.complete) {
    return line.hits.count;
  }
  const float t_from_low = 1.0f - line.reverse.t[size_t(kEndHits - 1)];
  return std::abs(t_from_low - line.hits.t[size_t(kEndHits)]) <= kSameCrossing ? kMaxLineHits
                                                                               : kMaxLineHits + 1;
}

/// Writes the hits of the casts into the compact field.
struct LineWriter {
  const GeometryImage& image;
  std::vector<uint8_t> patches;   ///< covered_patches(image)
  const glm::vec2* corner_uv;     ///< 3 per triangle of the parameterised mesh
  std::vector<uint8_t> inside;    ///< triangles_in_covered_patches(image, patches, corner uvs)
  std::vector<glm::vec3> points;  ///< sample_points(box, n)
  GeometryField& field;

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

  /// The hits of the line low -> high that the field stores, from `low`: all of a complete line;
  /// of a longer one the kEndHits nearest each end.
  LineHits stored_hits(int low, int high, const LineCast& line) const;

  /// Stores the `count` lines entry -> first.. and counts their rays into `histogram` by hits.
  void store_lines(int entry, int first, int count, const std::array<LineCast, 8>& lines,
                   Histogram& histogram, std::vector<TableLine>& table_lines) const {
    for (int lane = 0; lane < count; ++lane) {
      const LineCast& line = lines[size_t(lane)];
      if (!line.ray) {
        continue;
      }
      const int exit = first + lane;
      store_line(field, entry, exit, stored_hits(entry, exit, line), table_lines);
      histogram[size_t(hit_count(line))] += 2;
    }
  }
};

LineHits LineWriter::stored_hits(int low, int high, const LineCast& line) const {
  LineHits hits;
  if (line.complete) {
    for (int k = 0; k < line.hits.count; ++k) {
      hits.uv[size_t(k)] = hit_uv(line.hits, k, low, high);
    }
    hits.count = line.hits.count;
    return hits;
  }
  for (int k = 0; k < kEndHits; ++k) {
    hits.uv[size_t(k)] = hit_uv(line.hits, k, low, high);
    hits.uv[size_t(kMaxLineHits - 1 - k)] = hit_uv(line.reverse, k, high, low);
  }
  hits.count = kMaxLineHits;
  return hits;
}

}  // namespace

size_t field_memory_estimate(int samples_per_side, bool half_precision) {
  const size_t n2 = size_t(samples_per_side) * size_t(samples_per_side);
  return 6 * n2 * 5 * n2 * (sizeof(glm::vec2) + (half_precision ? 4 : 8));
}

double layer_coverage(const FieldBuildStats& stats, int layers) {
  if (stats.rays == 0) {
    return -1.0;
  }
  size_t held = 0;
  for (int h = 0; h <= std::min(layers, kMaxLineHits); ++h) {
    held += stats.lines_by_hits[size_t(h)];
  }
  return double(held) / double(stats.rays);
}

int layered_field_layers(const FieldBuildStats& stats, int requested) {
  if (requested != kAutoLayers) {
    return requested;
  }
  for (int k = 1; k < kMaxFieldLayers; ++k) {
    if (layer_coverage(stats, k) >= kLayerCoverage) {
      return k;
    }
  }
  return kMaxFieldLayers;
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

bool check_field_size(int samples_per_side, bool half_precision, std::string& error) {
  if (samples_per_side < kMinSamplesPerSide || samples_per_side > kMaxSamplesPerSide) {
    error = "samples per side " + std::to_string(samples_per_side) + " out of range [" +
            std::to_string(kMinSamplesPerSide) + ", " + std::to_string(kMaxSamplesPerSide) + "]";
    return false;
  }
  const size_t needed = field_memory_estimate(samples_per_side, half_precision);
  const size_t available = available_memory();
  if (available != 0 && needed > available) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "a field with N = %d needs about %.0f MB but only %.0f MB of memory is available",
                  samples_per_side, double(needed) / 1e6, double(available) / 1e6);
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
                          const GeometryImage& image, int samples_per_side, GeometryField& field,
                          std::string& error, FieldBuildStats* stats, const JobControl* control) {
  Stopwatch watch;
  if (image.size < 2 || image.coverage.size() != size_t(image.size) * size_t(image.size) ||
      image.position.size() != image.coverage.size()) {
    error = "the geometry image is empty or inconsistent";
    return false;
  }
  const int n = samples_per_side;
  if (n < kMinSamplesPerSide || n > kMaxSamplesPerSide) {
    error = "samples per side " + std::to_string(n) + " out of range [" +
            std::to_string(kMinSamplesPerSide) + ", " + std::to_string(kMaxSamplesPerSide) + "]";
    return false;
  }
  if (pm.corner_uv.size() != 3 * pm.mesh.triangles.size()) {
    error = "the parameterized mesh has " + std::to_string(pm.corner_uv.size()) +
            " corner uvs for " + std::to_string(pm.mesh.triangles.size()) + " triangles";
    return false;
  }
  field.samples_per_side = n;
  field.box = image.box;
  reset_field_tables(field);  // every entry is written below, line by line
  std::vector<uint8_t> patches = covered_patches(image);
  std::vector<uint8_t> inside = triangles_in_covered_patches(image, patches, pm.corner_uv);
  const LineWriter writer{.image = image,
                          .patches = std::move(patches),
                          .corner_uv = pm.corner_uv.data(),
                          .inside = std::move(inside),
                          .points = sample_points(image.box, n),
                          .field = field};
  PerThread<Histogram> histograms(Histogram{});
  PerThread<std::vector<TableLine>> table_lines;
  cast_lines(
      embree, writer.points, n, kLineCapacity, kEndHits,
      [&](int entry, int first, int count, const std::array<LineCast, 8>& lines) {
        writer.store_lines(entry, first, count, lines, histograms.local(), table_lines.local());
      },
      control);
  if (stop_requested(control)) {
    error = kInterrupted;
    return false;
  }
  std::vector<TableLine> all_table_lines;
  for (std::vector<TableLine>& part : table_lines) {
    all_table_lines.insert(all_table_lines.end(), part.begin(), part.end());
    std::vector<TableLine>().swap(part);
  }
  pack_line_table(all_table_lines, field);
  report_progress(control, "field", 1.0);

  FieldBuildStats s;
  const size_t side = size_t(sample_count(n));
  s.rays = side * side - 6 * size_t(n * n) * size_t(n * n);
  s.lines_by_hits = histograms.combine([](const Histogram& a, const Histogram& b) {
    Histogram sum;
    for (size_t h = 0; h < sum.size(); ++h) {
      sum[h] = a[h] + b[h];
    }
    return sum;
  });
  GF_CHECK_EQ(std::accumulate(s.lines_by_hits.begin(), s.lines_by_hits.end(), size_t(0)), s.rays,
              "every ray between samples on different faces cast once");
  s.hits = s.rays - s.lines_by_hits[0];
  s.seconds = watch.seconds();
  if (stats != nullptr) {
    *stats = s;
  }
  return true;
}

size_t cast_field_rays(const EmbreeMesh& embree, const Box& box, int samples_per_side, bool lines) {
  const std::vector<glm::vec3> points = sample_points(box, samples_per_side);
  PerThread<size_t> hits(size_t(0));
  if (!lines) {
    cast_first_hits(embree, points, samples_per_side,
                    [&](int, int, const std::array<HitList, 8>& lanes, bool) {
                      for (const HitList& list : lanes) {
                        hits.local() += size_t(list.count > 0);
                      }
                    });
  } else {
    cast_lines(embree, points, samples_per_side, kLineCapacity, kEndHits,
               [&](int, int, int count, const std::array<LineCast, 8>& cast) {
                 for (int lane = 0; lane < count; ++lane) {
                   const LineCast& line = cast[size_t(lane)];
                   const HitList& back = line.complete ? line.hits : line.reverse;
                   hits.local() += size_t(line.hits.count > 0) + size_t(back.count > 0);
                 }
               });
  }
  return hits.combine([](size_t a, size_t b) { return a + b; });
}

}  // namespace gfield
