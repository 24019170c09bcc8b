#include "preprocess/embree_mesh.hpp"

#include <limits>

namespace gfield {

std::string embree_error_text(RTCError e) {
  switch (e) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "an invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "an invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "an unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "error " + std::to_string(int(e));
  }
}

EmbreeMesh::~EmbreeMesh() {
  if (scene_) {
    rtcReleaseScene(scene_);
  }
  if (device_) {
    rtcReleaseDevice(device_);
  }
}

bool attach_triangle_mesh(RTCDevice device, RTCScene scene, const TriangleMesh& mesh) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree reads vertex buffers with 16-byte loads: rtcSetNewGeometryBuffer pads for that.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.positions.size()));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), mesh.triangles.size()));
  if (!vertices || !indices) {
    rtcReleaseGeometry(geometry);
    return false;
  }
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    for (int k = 0; k < 3; ++k) {
      vertices[3 * v + size_t(k)] = float(mesh.positions[v][k]);
    }
  }
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      indices[3 * f + size_t(k)] = unsigned(mesh.triangles[f][k]);
    }
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(scene, geometry, 0);
  rtcReleaseGeometry(geometry);
  return true;
}

bool EmbreeMesh::build(const TriangleMesh& mesh, std::string& error, RTCBuildQuality quality) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) {
    error =
        "Embree: cannot create a device (" + embree_error_text(rtcGetDeviceError(nullptr)) + ")";
    return false;
  }
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, quality);
  // Casts may pass an intersection filter in their context (the layered field build).
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  if (!attach_triangle_mesh(device_, scene_, mesh)) {
    error = "Embree: cannot allocate buffers for " + std::to_string(mesh.triangles.size()) +
            " triangles";
    return false;
  }
  rtcCommitScene(scene_);
  if (const RTCError e = rtcGetDeviceError(device_); e != RTC_ERROR_NONE) {
    error = "Embree: building the BVH of " + std::to_string(mesh.triangles.size()) +
            " triangles failed (" + embree_error_text(e) + ")";
    return false;
  }
  return true;
}

void init_rayhit(RTCRayHit& rh, glm::vec3 origin, glm::vec3 direction, float t_near, float t_far) {
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = direction.x;
  rh.ray.dir_y = direction.y;
  rh.ray.dir_z = direction.z;
  rh.ray.tnear = t_near;
  rh.ray.tfar = t_far;
  rh.ray.time = 0.0f;
  rh.ray.mask = 0xffffffffu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

namespace {

/// Embree's intersect context with the triangle a ray must not hit.
struct IgnoreContext {
  RTCIntersectContext embree;  // first: Embree hands the filter a pointer to it
  unsigned ignored = RTC_INVALID_GEOMETRY_ID;
};

void reject_ignored(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const IgnoreContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (RTCHitN_primID(args->hit, args->N, i) == context->ignored) {
      args->valid[i] = 0;
    }
  }
}

}  // namespace

RayHit intersect(const EmbreeMesh& mesh, glm::vec3 origin, glm::vec3 direction, float t_near,
                 float t_far, int ignored) {
  IgnoreContext context;
  rtcInitIntersectContext(&context.embree);
  if (ignored >= 0) {
    context.ignored = unsigned(ignored);
    context.embree.filter = reject_ignored;
  }
  RTCRayHit rh;
  init_rayhit(rh, origin, direction, t_near, t_far);
  rtcIntersect1(mesh.scene(), &context.embree, &rh);
  RayHit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
    return hit;
  }
  hit.hit = true;
  hit.t = rh.ray.tfar;
  hit.triangle = int(rh.hit.primID);
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  hit.geometric_normal = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
  return hit;
}

}  // namespace gfield
