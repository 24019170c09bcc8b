#pragma once
// The Embree casts of a geometry-field build (field_build.hpp). The table's rays run from every
// one of the 6 N^2 box samples to every sample on another face, t in [0, 1]; the ray exit ->
// entry is the ray entry -> exit reversed, one line of space with the same hits.
//
// - First hits (K = 1, and the benchmark's reference): a bare first-hit cast of every ray, in
//   coherent packets of 8 (one entry sample, 8 consecutive exit samples).
// - Lines (K > 1): one traversal per line (entry < exit) collects its hits nearest the entry up
//   to a capacity, which hands both rays all their hits when the line holds fewer; a second
//   traversal from the exit's side runs only for a line that fills the list. Lines are visited
//   in square tiles of the table, so that the reversed rays' entries (a column) are written
//   while they are in cache.

#include <array>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/box.hpp"
#include "preprocess/embree_mesh.hpp"
#include "preprocess/job_control.hpp"

namespace gfield {

/// Hits kept per traversal at most.
inline constexpr int kMaxHitList = 8;

/// Two hits of one line closer than this (in t, the line's length being 1) are one crossing of
/// the surface: a ray through an edge or a vertex hits every triangle there.
inline constexpr float kSameCrossing = 1e-6f;

/// The nearest hits of one traversal, sorted by t (t along the traversal's ray).
struct HitList {
  int count = 0;
  std::array<float, kMaxHitList> t{};
  std::array<unsigned, kMaxHitList> triangle{};
  std::array<glm::vec2, kMaxHitList> barycentric{};  ///< Embree's (u, v) on the triangle
};

/// The 6 N^2 sample points in mesh coordinates, by sample index.
std::vector<glm::vec3> sample_points(const Box& box, int n);

/// Called once per packet of first hits with the entry sample, the packet's first exit sample
/// and the 8 rays' first hits (count 0: a miss, a ray on the entry's face or past the row's end).
/// `cast` is false for a packet lying wholly on the entry's face. Called from several threads.
using FirstHitConsumer =
    std::function<void(int entry, int first_exit, const std::array<HitList, 8>& lanes, bool cast)>;

/// First hits of every ray; `points` = sample_points(box, N). `control` (optional) hears the
/// share of the entry rows done (stage "field") and, once it asks to stop, the remaining rows
/// are skipped (the caller checks stop_requested).
void cast_first_hits(const EmbreeMesh& embree, const std::vector<glm::vec3>& points, int n,
                     const FirstHitConsumer& consume, const JobControl* control = nullptr);

/// One line entry -> exit (entry <= exit) of cast_lines.
struct LineCast {
  bool ray = false;  ///< false: entry and exit on one face, or exit past the row's end
  HitList hits;      ///< the hits nearest the entry, t along entry -> exit
  /// hits.count < the capacity: `hits` are all the line's hits, and reversed they are the exit
  /// ray's. Otherwise `reverse` holds the exit ray's nearest hits, t along exit -> entry.
  bool complete = true;
  HitList reverse;
};

/// Called once per packet of lines with the entry sample, the packet's first exit sample and its
/// lines: exits first..first+count-1 (count <= 8; the lanes past them belong to another tile).
/// Called from several threads at once, never for one line twice.
using LineConsumer =
    std::function<void(int entry, int first_exit, int count, const std::array<LineCast, 8>& lines)>;

/// Visits every line (entry, exit) with entry <= exit once (tile by tile): collects up to
/// `capacity` hits nearest the entry (1..kMaxHitList) and, for lines whose list is full, up to
/// `reverse_capacity` hits nearest the exit. `control` as for cast_first_hits, per tile.
void cast_lines(const EmbreeMesh& embree, const std::vector<glm::vec3>& points, int n, int capacity,
                int reverse_capacity, const LineConsumer& consume,
                const JobControl* control = nullptr);

}  // namespace gfield
