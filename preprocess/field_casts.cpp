#include "preprocess/field_casts.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace gfield {
namespace {

/// Embree's intersect context extended by the hit lists of the packet's 8 lanes (ray id = lane).
struct CollectContext {
  RTCIntersectContext embree;  // first: Embree hands the filter a pointer to it
  int capacity = 1;
  std::array<HitList, 8>* lanes = nullptr;
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
    HitList& list = (*context->lanes)[RTCRayN_id(args->ray, args->N, i)];
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

/// Sets lane `lane` of `packet` to the ray origin + t direction, t in [t_near, t_far].
void set_lane(RTCRayHit8& packet, int lane, glm::vec3 origin, glm::vec3 direction, float t_near,
              float t_far) {
  packet.ray.org_x[lane] = origin.x;
  packet.ray.org_y[lane] = origin.y;
  packet.ray.org_z[lane] = origin.z;
  packet.ray.dir_x[lane] = direction.x;
  packet.ray.dir_y[lane] = direction.y;
  packet.ray.dir_z[lane] = direction.z;
  packet.ray.tnear[lane] = t_near;
  packet.ray.tfar[lane] = t_far;
  packet.ray.time[lane] = 0.0f;
  packet.ray.mask[lane] = 0xFFFFFFFFu;
  packet.ray.id[lane] = unsigned(lane);
  packet.ray.flags[lane] = 0;
  packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
  packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
}

/// Casts `packet` (lanes with valid[lane] != 0) and leaves each lane's nearest hits in `lanes`
/// (cleared first): with `context.capacity` 1 a plain first-hit cast, else the collecting filter.
void cast_packet(const EmbreeMesh& embree, CollectContext& context, const int* valid,
                 RTCRayHit8& packet, std::array<HitList, 8>& lanes) {
  for (HitList& list : lanes) {
    list.count = 0;
  }
  context.lanes = &lanes;
  rtcIntersect8(valid, embree.scene(), &context.embree, &packet);
  if (context.capacity > 1) {
    return;
  }
  for (int lane = 0; lane < 8; ++lane) {
    if (valid[lane] != 0 && packet.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID) {
      lanes[size_t(lane)].count = 1;
      lanes[size_t(lane)].t[0] = packet.ray.tfar[lane];
      lanes[size_t(lane)].triangle[0] = packet.hit.primID[lane];
      lanes[size_t(lane)].barycentric[0] = {packet.hit.u[lane], packet.hit.v[lane]};
    }
  }
}

/// A context for packets of one thread: coherent or not, collecting `capacity` hits per ray.
CollectContext make_context(int capacity, bool coherent) {
  CollectContext context;
  rtcInitIntersectContext(&context.embree);
  context.embree.flags =
      coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  context.embree.filter = capacity > 1 ? collect_hits : nullptr;
  context.capacity = capacity;
  return context;
}

/// The lines entry -> first..first+7 (exits below `end`, none before the entry): casts the
/// packet of those on different faces and, for lines whose list came back full, the packet of
/// their reversed rays.
void cast_line_packet(const EmbreeMesh& embree, const std::vector<glm::vec3>& points, int n,
                      int entry, int first, int end, CollectContext& forward,
                      CollectContext& reverse, std::array<LineCast, 8>& lines) {
  const int per_face = n * n;
  alignas(32) RTCRayHit8 packet;
  alignas(32) int valid[8];
  std::array<HitList, 8> hits;
  bool any = false;
  const glm::vec3 a = points[size_t(entry)];
  for (int lane = 0; lane < 8; ++lane) {
    const int exit = first + lane;
    LineCast& line = lines[size_t(lane)];
    line.ray = exit < end && exit / per_face != entry / per_face;
    line.hits.count = 0;
    line.complete = true;
    valid[lane] = line.ray ? -1 : 0;
    any = any || line.ray;
    set_lane(packet, lane, a, line.ray ? points[size_t(exit)] - a : glm::vec3(1.0f), 0.0f, 1.0f);
  }
  if (!any) {
    return;
  }
  cast_packet(embree, forward, valid, packet, hits);
  any = false;
  for (int lane = 0; lane < 8; ++lane) {
    LineCast& line = lines[size_t(lane)];
    line.hits = hits[size_t(lane)];
    line.complete = line.hits.count < forward.capacity;
    valid[lane] = line.ray && !line.complete ? -1 : 0;
    any = any || valid[lane] != 0;
  }
  if (!any) {
    return;
  }
  for (int lane = 0; lane < 8; ++lane) {
    const glm::vec3 b = valid[lane] != 0 ? points[size_t(first + lane)] : a;
    set_lane(packet, lane, b, a - b + glm::vec3(float(valid[lane] == 0)), 0.0f, 1.0f);
  }
  cast_packet(embree, reverse, valid, packet, hits);
  for (int lane = 0; lane < 8; ++lane) {
    if (valid[lane] != 0) {
      lines[size_t(lane)].reverse = hits[size_t(lane)];
    }
  }
}

/// Side of the square tiles in which cast_lines visits the table.
constexpr int kTile = 64;

/// The casts' units of work (entry rows, tiles) for a JobControl: next() before each unit reports
/// the share started so far and says whether to go on.
class Countdown {
 public:
  Countdown(const JobControl* control, int units) : control_(control), units_(units) {}

  bool next() {
    if (control_ == nullptr) {
      return true;
    }
    if (stop_requested(control_)) {
      return false;
    }
    const int started = started_.fetch_add(1, std::memory_order_relaxed);
    report_progress(control_, "field", double(started) / double(units_));
    return true;
  }

 private:
  const JobControl* control_;
  int units_;
  std::atomic<int> started_{0};
};

}  // namespace

std::vector<glm::vec3> sample_points(const Box& box, int n) {
  std::vector<glm::vec3> points(size_t(sample_count(n)));
  for (int k = 0; k < sample_count(n); ++k) {
    points[size_t(k)] = from_unit_cube(box, sample_point(face_sample(k, n), n));
  }
  return points;
}

void cast_first_hits(const EmbreeMesh& embree, const std::vector<glm::vec3>& points, int n,
                     const FirstHitConsumer& consume, const JobControl* control) {
  const int side = int(points.size());
  const int per_face = n * n;
  Countdown rows_done(control, side);
  tbb::parallel_for(tbb::blocked_range<int>(0, side), [&](const tbb::blocked_range<int>& rows) {
    CollectContext context = make_context(1, true);
    alignas(32) RTCRayHit8 packet;
    alignas(32) int valid[8];
    std::array<HitList, 8> lanes;
    for (int entry = rows.begin(); entry != rows.end(); ++entry) {
      if (!rows_done.next()) {
        return;
      }
      const glm::vec3 origin = points[size_t(entry)];
      const int face_begin = (entry / per_face) * per_face;
      const int face_end = face_begin + per_face;
      for (int first = 0; first < side; first += 8) {
        for (HitList& list : lanes) {
          list.count = 0;
        }
        if (first >= face_begin && first + 8 <= face_end) {
          consume(entry, first, lanes, false);  // the packet lies on the entry's face
          continue;
        }
        bool any = false;
        for (int lane = 0; lane < 8; ++lane) {
          const int exit = first + lane;
          const bool ray = exit < side && (exit < face_begin || exit >= face_end);
          valid[lane] = ray ? -1 : 0;
          any = any || ray;
          const glm::vec3 direction = ray ? points[size_t(exit)] - origin : glm::vec3(1.0f);
          set_lane(packet, lane, origin, direction, 0.0f, 1.0f);
        }
        if (any) {
          cast_packet(embree, context, valid, packet, lanes);
        }
        consume(entry, first, lanes, true);
      }
    }
  });
}

void cast_lines(const EmbreeMesh& embree, const std::vector<glm::vec3>& points, int n, int capacity,
                int reverse_capacity, const LineConsumer& consume, const JobControl* control) {
  const int side = int(points.size());
  const int tiles = (side + kTile - 1) / kTile;
  Countdown tiles_done(control, tiles * (tiles + 1) / 2);
  // Tile pairs (row tile r <= column tile c), numbered r * tiles + c.
  tbb::parallel_for(
      tbb::blocked_range<int>(0, tiles * tiles), [&](const tbb::blocked_range<int>& range) {
        CollectContext forward = make_context(std::clamp(capacity, 1, kMaxHitList), true);
        CollectContext reverse = make_context(std::clamp(reverse_capacity, 1, kMaxHitList), false);
        std::array<LineCast, 8> lines;
        for (int tile = range.begin(); tile != range.end(); ++tile) {
          const int row_tile = tile / tiles;
          const int column_tile = tile % tiles;
          if (row_tile > column_tile) {
            continue;
          }
          if (!tiles_done.next()) {
            return;
          }
          const int end = std::min(side, (column_tile + 1) * kTile);
          for (int entry = row_tile * kTile; entry < std::min(side, (row_tile + 1) * kTile);
               ++entry) {
            for (int first = std::max(entry, column_tile * kTile); first < end; first += 8) {
              cast_line_packet(embree, points, n, entry, first, end, forward, reverse, lines);
              consume(entry, first, std::min(8, end - first), lines);
            }
          }
        }
      });
}

}  // namespace gfield
