#include "preprocess/field_build.hpp"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

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

/// Casts every ray of the table in packets of 8 and hands each packet of 8 consecutive exits to
/// `consume(entry, first_exit, valid, rayhit, cast)`. Exits on the entry's face (and past the end
/// of the row) are invalid lanes; a packet with no valid lane is not cast (cast = false).
template <class Consume>
void cast_packets(const EmbreeMesh& embree, const Box& box, int n, Consume&& consume) {
  const std::vector<glm::vec3> points = sample_points(box, n);
  const int side = sample_count(n);
  const int per_face = n * n;
  tbb::parallel_for(tbb::blocked_range<int>(0, side), [&](const tbb::blocked_range<int>& rows) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(32) RTCRayHit8 packet;
    alignas(32) int valid[8];
    for (int entry = rows.begin(); entry != rows.end(); ++entry) {
      const glm::vec3 origin = points[size_t(entry)];
      const int face_begin = (entry / per_face) * per_face;
      const int face_end = face_begin + per_face;
      for (int first = 0; first < side; first += 8) {
        if (first >= face_begin && first + 8 <= face_end) {
          consume(entry, first, valid, packet, false);  // the packet lies on the entry's face
          continue;
        }
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
        if (any) {
          rtcIntersect8(valid, embree.scene(), &context, &packet);
        }
        consume(entry, first, valid, packet, any);
      }
    }
  });
}

}  // namespace

size_t field_memory_estimate(int samples_per_side, bool half_precision) {
  const size_t side = size_t(sample_count(samples_per_side));
  return side * side * (sizeof(glm::vec2) + (half_precision ? 4 : 8));
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
                          const GeometryImage& image, int samples_per_side, GeometryField& field,
                          std::string& error, FieldBuildStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const Box& box = image.box;
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
  const size_t side = size_t(sample_count(n));
  field.samples_per_side = n;
  field.box = box;
  field.uv.resize(side * side);  // every entry is written below, row by row

  const glm::vec2* corner_uv = pm.corner_uv.data();
  const std::vector<glm::vec3> points = sample_points(box, n);
  const std::vector<uint8_t> patches = covered_patches(image);
  glm::vec2* table = field.uv.data();
  tbb::combinable<size_t> hits(size_t(0));
  cast_packets(
      embree, box, n, [&](int entry, int first, const int* valid, const RTCRayHit8& p, bool cast) {
        glm::vec2* row = table + size_t(entry) * side;
        const int lanes = std::min(8, int(side) - first);
        if (!cast) {
          std::fill_n(row + first, lanes, glm::vec2(kFieldNoRay));
          return;
        }
        size_t& local_hits = hits.local();
        for (int lane = 0; lane < lanes; ++lane) {
          glm::vec2 value(kFieldNoRay);
          if (valid[lane] != 0) {
            value = glm::vec2(kFieldMiss);
            if (p.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID) {
              const glm::vec2* uv = corner_uv + 3 * size_t(p.hit.primID[lane]);
              const float u = p.hit.u[lane];
              const float v = p.hit.v[lane];
              // Corner uvs of faces across the image border (orbifold copies)
              // may leave [0,1]^2 a little: clamp as GL_CLAMP_TO_EDGE would.
              value = glm::clamp((1.0f - u - v) * uv[0] + u * uv[1] + v * uv[2], 0.0f, 1.0f);
              const glm::vec3 origin = points[size_t(entry)];
              const glm::vec3 hit =
                  origin + p.ray.tfar[lane] * (points[size_t(first + lane)] - origin);
              value = snap_to_covered(image, patches, value, hit);
              ++local_hits;
            }
          }
          row[first + lane] = value;
        }
      });

  if (stats != nullptr) {
    stats->rays = side * side - 6 * size_t(n * n) * size_t(n * n);
    stats->hits = hits.combine([](size_t a, size_t b) { return a + b; });
    stats->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return true;
}

size_t cast_field_rays(const EmbreeMesh& embree, const Box& box, int samples_per_side) {
  tbb::combinable<size_t> hits(size_t(0));
  cast_packets(embree, box, samples_per_side,
               [&](int, int, const int* valid, const RTCRayHit8& p, bool cast) {
                 if (!cast) {
                   return;
                 }
                 size_t& local_hits = hits.local();
                 for (int lane = 0; lane < 8; ++lane) {
                   local_hits +=
                       size_t(valid[lane] != 0 && p.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID);
                 }
               });
  return hits.combine([](size_t a, size_t b) { return a + b; });
}

}  // namespace gfield
