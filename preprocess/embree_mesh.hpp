#pragma once
// An Embree 3 device and scene holding one triangle mesh, for exact ray casts (the ground truth
// of the project: field build, verify, tests). Float vertices in mesh coordinates.

#include <embree3/rtcore.h>

#include <string>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"

namespace gfield {

/// What an Embree error code means, in words ("out of memory", ...).
std::string embree_error_text(RTCError error);

/// Attaches `mesh` to `scene` (of `device`) as its geometry 0, a committed triangle geometry of
/// its positions rounded to float (primID = triangle index). False when Embree cannot allocate
/// its buffers.
bool attach_triangle_mesh(RTCDevice device, RTCScene scene, const TriangleMesh& mesh);

/// Owns an RTCDevice and an RTCScene with the mesh as geometry 0 (primID = triangle index).
/// Build quality MEDIUM, non-robust (DESIGN.md: fastest to build at equal cast speed).
class EmbreeMesh {
 public:
  EmbreeMesh() = default;
  ~EmbreeMesh();
  EmbreeMesh(const EmbreeMesh&) = delete;
  EmbreeMesh& operator=(const EmbreeMesh&) = delete;

  /// Builds the BVH of `mesh` (`quality`: LOW for a BVH built for few queries). False with an
  /// error if Embree refuses the device or geometry.
  bool build(const TriangleMesh& mesh, std::string& error,
             RTCBuildQuality quality = RTC_BUILD_QUALITY_MEDIUM);

  RTCDevice device() const { return device_; }
  RTCScene scene() const { return scene_; }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

/// The first hit of one ray: t along the (unnormalised) direction, triangle, Embree barycentrics
/// (hit = (1-u-v) p0 + u p1 + v p2) and the geometric normal (unnormalised, Embree's Ng).
struct RayHit {
  bool hit = false;
  float t = 0.0f;
  int triangle = -1;
  float u = 0.0f;
  float v = 0.0f;
  glm::vec3 geometric_normal{0.0f};
};

/// Casts origin + t * direction for t in [t_near, t_far] with rtcIntersect1, ignoring triangle
/// `ignored` (>= 0: a ray leaving that triangle's surface; an intersection filter rejects it).
RayHit intersect(const EmbreeMesh& mesh, glm::vec3 origin, glm::vec3 direction, float t_near = 0.0f,
                 float t_far = 3.0e38f, int ignored = -1);

/// Initialises an Embree RTCRay(Hit) with the fields DESIGN.md warns about (mask = -1, flags = 0,
/// geomID = instID = RTC_INVALID_GEOMETRY_ID).
void init_rayhit(RTCRayHit& rayhit, glm::vec3 origin, glm::vec3 direction, float t_near,
                 float t_far);

}  // namespace gfield
