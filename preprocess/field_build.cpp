#include "preprocess/field_build.hpp"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>
#include "gfield/stopwatch.hpp"

namespace gfield {
namespace {

/// The 6 N^2 sample points in mesh coordinates, by sample index.
std::vector<glm::vec3> sample_points(const Box& box, int n) {
  std::vector<glm::vec3> points(size_t(sample_count(n)));
  for (int k = 0; k < sample_count(n); ++k) {
    points[size_t(k)] = from_unit_cube(box, sample_point(face_sample(k, n), n));
  }
  return points;
}

/// Hits looked for per line at most (kAutoLayers: one more than can be stored, to count the
/// lines with more hits than layers).
constexpr int kMaxCollected = kMaxFieldLayers + 1;
/// Two hits of one line closer than this (in t, the line's length being 1) are one crossing of
/// the surface: a ray through an edge or a vertex hits every triangle there.
constexpr float kSameCrossing = 1e-6f;

/// The nearest hits of one ray found so far, sorted by t.
struct HitList {
  int count = 0;
  std::array<float, kMaxCollected> t{};
  std::array<unsigned, kMaxCollected> triangle{};
  std::array<glm::vec2, kMaxCollected> barycentric{};
};

/// Embree's intersect context extended by the hit lists of the packet's 8 lanes (ray id = lane).
struct CollectContext {
  RTCIntersectContext embree;  // first: Embree hands the filter a pointer to it
  int capacity = 1;
  std::array<HitList, 8> lanes;
};

/// Inserts a hit into `list` (the `capacity` nearest are kept; a second hit at the same t is one
/// crossing, dropped).
void insert_hit(HitList& list, int capacity, float t, unsigned triangle, glm::vec2 uv) {
  for (int k = 0; k < list.count; ++k) {
    if (std::abs(list.t[size_t(k)] - t) <= kSameCrossing) {
      return;
    }
  }
  int k = std::min(list.count, capacity - 1);
  if (list.count == capacity && t >= list.t[size_t(k)]) {
    return;
  }
  for (; k > 0 && list.t[size_t(k - 1)] > t; --k) {
    list.t[size_t(k)] = list.t[size_t(k - 1)];
    list.triangle[size_t(k)] = list.triangle[size_t(k - 1)];
    list.barycentric[size_t(k)] = list.barycentric[size_t(k - 1)];
  }
  list.t[size_t(k)] = t;
  list.triangle[size_t(k)] = triangle;
  list.barycentric[size_t(k)] = uv;
  list.count = std::min(list.count + 1, capacity);
}

/// The intersection filter (RTCIntersectContext::filter) that collects every ray's nearest hits:
/// called by Embree for each potential hit with the hit distance in tfar. While the list is not
/// full the hit is rejected, so that traversal goes on; once it is, the hit is accepted with
/// tfar set to the list's farthest hit (Embree keeps the tfar of an accepted hit), so that
/// traversal culls everything beyond the capacity-th nearest hit.
void collect_hits(const RTCFilterFunctionNArguments* args) {
  auto* context = reinterpret_cast<CollectContext*>(args->context);
  const int capacity = context->capacity;
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) {
      continue;
    }
    HitList& list = context->lanes[RTCRayN_id(args->ray, args->N, i)];
    float& tfar = RTCRayN_tfar(args->ray, args->N, i);
    const glm::vec2 uv(RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
    insert_hit(list, capacity, tfar, RTCHitN_primID(args->hit, args->N, i), uv);
    if (list.count < capacity) {
      args->valid[i] = 0;
      continue;
    }
    tfar = list.t[size_t(capacity - 1)];
  }
}

/// Sets up the 8 lanes of the packet from `origin` to the exits first..first+7 (lanes on the
/// entry's face [face_begin, face_end) or past the row's end are invalid). False when no lane is.
bool fill_packet(const std::vector<glm::vec3>& points, glm::vec3 origin, int first, int face_begin,
                 int face_end, RTCRayHit8& packet, int* valid) {
  const int side = int(points.size());
  bool any = false;
  for (int lane = 0; lane < 8; ++lane) {
    const int exit = first + lane;
    const bool ray = exit < side && (exit < face_begin || exit >= face_end);
    valid[lane] = ray ? -1 : 0;
    any = any || ray;
    const glm::vec3 direction = ray ? points[size_t(exit)] - origin : glm::vec3(1.0f);
    packet.ray.org_x[lane] = origin.x;
    packet.ray.org_y[lane] = origin.y;
    packet.ray.org_z[lane] = origin.z;
    packet.ray.dir_x[lane] = direction.x;
    packet.ray.dir_y[lane] = direction.y;
    packet.ray.dir_z[lane] = direction.z;
    packet.ray.tnear[lane] = 0.0f;
    packet.ray.tfar[lane] = 1.0f;
    packet.ray.time[lane] = 0.0f;
    packet.ray.mask[lane] = 0xFFFFFFFFu;
    packet.ray.id[lane] = unsigned(lane);
    packet.ray.flags[lane] = 0;
    packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
  }
  return any;
}

/// Casts every ray of the table in packets of 8, collecting up to `capacity` nearest hits per
/// ray (1: a plain first-hit cast, no filter), and hands each packet of 8 consecutive exits to
/// `consume(entry, first_exit, lanes, cast)` (lanes: the 8 rays' hit lists, count 0 for a miss or
/// an invalid lane). A packet lying on the entry's face is not cast (cast = false).
template <class Consume>
void cast_packets(const EmbreeMesh& embree, const Box& box, int n, int capacity,
                  Consume&& consume) {
  const std::vector<glm::vec3> points = sample_points(box, n);
  const int side = sample_count(n);
  const int per_face = n * n;
  tbb::parallel_for(tbb::blocked_range<int>(0, side), [&](const tbb::blocked_range<int>& rows) {
    CollectContext context;
    rtcInitIntersectContext(&context.embree);
    context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    context.embree.filter = capacity > 1 ? collect_hits : nullptr;
    context.capacity = capacity;
    alignas(32) RTCRayHit8 packet;
    alignas(32) int valid[8];
    for (int entry = rows.begin(); entry != rows.end(); ++entry) {
      const glm::vec3 origin = points[size_t(entry)];
      const int face_begin = (entry / per_face) * per_face;
      const int face_end = face_begin + per_face;
      for (int first = 0; first < side; first += 8) {
        for (HitList& list : context.lanes) {
          list.count = 0;
        }
        if (first >= face_begin && first + 8 <= face_end) {
          consume(entry, first, context.lanes, false);  // the packet lies on the entry's face
          continue;
        }
        if (!fill_packet(points, origin, first, face_begin, face_end, packet, valid)) {
          consume(entry, first, context.lanes, true);
          continue;
        }
        rtcIntersect8(valid, embree.scene(), &context.embree, &packet);
        for (int lane = 0; lane < 8 && capacity == 1; ++lane) {
          if (valid[lane] != 0 && packet.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID) {
            context.lanes[size_t(lane)].count = 1;
            context.lanes[size_t(lane)].t[0] = packet.ray.tfar[lane];
            context.lanes[size_t(lane)].triangle[0] = packet.hit.primID[lane];
            context.lanes[size_t(lane)].barycentric[0] = {packet.hit.u[lane], packet.hit.v[lane]};
          }
        }
        consume(entry, first, context.lanes, true);
      }
    }
  });
}

/// Rays by number of hits found (FieldBuildStats::lines_by_hits).
using Histogram = std::array<size_t, kMaxFieldLayers + 2>;

/// Writes the hits of a packet's rays into the layers of the table.
struct TableWriter {
  const GeometryImage& image;
  std::vector<uint8_t> patches;   ///< covered_patches(image)
  const glm::vec2* corner_uv;     ///< 3 per triangle of the parameterised mesh
  std::vector<glm::vec3> points;  ///< sample_points(box, n)
  int n;
  int stored;    ///< layers written
  int capacity;  ///< hits collected per ray
  glm::vec2* table;

  /// The uv of hit `k` of `list` on the ray from `entry` to `exit`: the hit triangle's corner uvs
  /// interpolated with the barycentrics, clamped to [0,1]^2 (corner uvs of faces across the
  /// image border, orbifold copies, may leave it a little, as GL_CLAMP_TO_EDGE would), snapped
  /// to a covered patch.
  glm::vec2 hit_uv(const HitList& list, int k, int entry, int exit) const {
    const glm::vec2* uv = corner_uv + 3 * size_t(list.triangle[size_t(k)]);
    const glm::vec2 b = list.barycentric[size_t(k)];
    const glm::vec2 value =
        glm::clamp((1.0f - b.x - b.y) * uv[0] + b.x * uv[1] + b.y * uv[2], 0.0f, 1.0f);
    const glm::vec3 origin = points[size_t(entry)];
    const glm::vec3 hit = origin + list.t[size_t(k)] * (points[size_t(exit)] - origin);
    return snap_to_covered(image, patches, value, hit);
  }

  /// Stores the rays from `entry` to exits first..first+7 (past the row's end: none) and counts
  /// them into `histogram` by hits found.
  void store(int entry, int first, const std::array<HitList, 8>& lanes, bool cast,
             Histogram& histogram) const {
    const size_t side = points.size();
    const size_t count = side * side;
    const int per_face = n * n;
    const int valid_lanes = std::min(8, int(side) - first);
    for (int lane = 0; lane < valid_lanes; ++lane) {
      const int exit = first + lane;
      const bool ray = cast && exit / per_face != entry / per_face;
      const HitList& list = lanes[size_t(lane)];
      histogram[size_t(std::min(list.count, capacity))] += size_t(ray);
      for (int layer = 0; layer < stored; ++layer) {
        glm::vec2 value(ray ? kFieldMiss : kFieldNoRay);
        if (ray && layer < list.count) {
          value = hit_uv(list, layer, entry, exit);
        }
        table[size_t(layer) * count + size_t(entry) * side + size_t(exit)] = value;
      }
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
  const glm::vec2 x = glm::clamp(uv * float(n) - 0.5f, glm::vec2(0.0f), glm::vec2(float(n - 1)));
  const glm::ivec2 c = glm::min(glm::ivec2(glm::floor(x)), glm::ivec2(n - 2));
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
                          GeometryField& field, std::string& error, FieldBuildStats* stats) {
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
  field.uv.resize(count * size_t(stored));  // every entry is written below, row by row

  const TableWriter writer{.image = image,
                           .patches = covered_patches(image),
                           .corner_uv = pm.corner_uv.data(),
                           .points = sample_points(image.box, n),
                           .n = n,
                           .stored = stored,
                           .capacity = capacity,
                           .table = field.uv.data()};
  tbb::combinable<Histogram> histograms(Histogram{});
  cast_packets(embree, image.box, n, capacity,
               [&](int entry, int first, const std::array<HitList, 8>& lanes, bool cast) {
                 writer.store(entry, first, lanes, cast, histograms.local());
               });

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
  tbb::combinable<size_t> hits(size_t(0));
  cast_packets(embree, box, samples_per_side, std::clamp(layers, 1, kMaxCollected),
               [&](int, int, const std::array<HitList, 8>& lanes, bool) {
                 size_t& local_hits = hits.local();
                 for (const HitList& list : lanes) {
                   local_hits += size_t(list.count > 0);
                 }
               });
  return hits.combine([](size_t a, size_t b) { return a + b; });
}

}  // namespace gfield
