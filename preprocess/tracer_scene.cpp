#include "preprocess/tracer_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "geometry/analytic_primitives.hpp"
#include "geometry/outward_normals.hpp"
#include "gfield/limits.hpp"
#include "preprocess/embree_mesh.hpp"

namespace gfield {
namespace {

/// World ray vs world AABB (slab test); true if it may hit within (0, t_max).
bool overlaps(const TracerRay& ray, glm::dvec3 lo, glm::dvec3 hi, double t_max) {
  double t0 = 0.0, t1 = t_max;
  for (int i = 0; i < 3; ++i) {
    const double inv = 1.0 / ray.direction[i];
    double ta = (lo[i] - ray.origin[i]) * inv;
    double tb = (hi[i] - ray.origin[i]) * inv;
    if (std::isnan(ta) || std::isnan(tb))
      continue;  // parallel and on the slab boundary
    if (ta > tb)
      std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1)
      return false;
  }
  return true;
}

/// Checks that every ray Embree sees stays far inside its limits (|origin| <= 1.8e18): each mesh
/// object within +-kMaxCoordinate in world coordinates, and the scene's box (camera, point
/// lights, objects) within +-kMaxAssetCoordinate in the coordinates of each mesh object, where
/// Embree intersects its instances. Analytic objects were checked when the scene was read. False
/// with "SCENE: objects[I] (MESH): problem".
bool check_reach(const Scene& scene, const std::vector<ObjectRecord>& objects, std::string& error) {
  glm::dvec3 lo(scene.camera.position), hi(scene.camera.position);
  for (const Light& light : scene.lights) {
    if (light.type == LightType::kPoint) {
      lo = glm::min(lo, glm::dvec3(light.position));
      hi = glm::max(hi, glm::dvec3(light.position));
    }
  }
  for (const ObjectRecord& r : objects) {
    lo = glm::min(lo, r.world_lo);
    hi = glm::max(hi, r.world_hi);
  }
  // World coordinates first: a mesh far out makes the scene's box large for every other mesh.
  char text[160];
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t i = 0; i < objects.size(); ++i) {
      const ObjectRecord& r = objects[i];
      const double reach = pass == 0 ? box_reach(glm::dmat4(1.0), r.world_lo, r.world_hi)
                                     : box_reach(r.to_object, lo, hi);
      if (r.object.shape.type != ShapeType::kMesh ||
          reach <= (pass == 0 ? kMaxCoordinate : kMaxAssetCoordinate)) {
        continue;
      }
      std::snprintf(text, sizeof(text),
                    pass == 0 ? "reaches %.3g in world coordinates after its transform (limit 1e15)"
                              : "the scene reaches %.3g in the mesh's own coordinates (limit "
                                "1e16: a scale too small for the scene's extent)",
                    reach);
      error = scene.filename + ": objects[" + std::to_string(i) + "] (" +
              scene.meshes[size_t(r.object.shape.mesh)].file + "): " + text;
      return false;
    }
  }
  return true;
}
}  // namespace

TracerScene::~TracerScene() {
  for (MeshRecord& m : meshes) {
    if (m.scene)
      rtcReleaseScene(m.scene);
  }
  if (top)
    rtcReleaseScene(top);
  if (device)
    rtcReleaseDevice(device);
}

bool TracerScene::build_mesh(MeshRecord& record, const MeshAsset& asset, std::string& error) {
  const std::string& file = asset.file;
  std::vector<std::string> warnings;  // the tools print them when they read the scene
  if (!load_mesh(MeshSource{asset.file, asset.part, asset.outside_paths}, record.mesh,
                 &record.appearance, warnings, error))
    return false;
  const TriangleMesh& mesh = record.mesh;
  record.orientation = outward_orientation(mesh);
  record.vertex_normals = outward_vertex_normals(mesh);
  record.scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(record.scene, RTC_BUILD_QUALITY_MEDIUM);
  if (!attach_triangle_mesh(device, record.scene, mesh)) {
    error = file + ": Embree cannot allocate the mesh buffers";
    return false;
  }
  rtcCommitScene(record.scene);
  return true;
}

bool TracerScene::build(const Scene& input, std::string& error) {
  scene = input;
  if (!load_environment(scene.environment, environment, error))
    return false;
  device = rtcNewDevice(nullptr);
  if (!device) {
    error = scene.filename + ": Embree cannot create a device";
    return false;
  }
  top = rtcNewScene(device);
  rtcSetSceneBuildQuality(top, RTC_BUILD_QUALITY_MEDIUM);
  meshes.resize(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    if (!build_mesh(meshes[m], scene.meshes[m], error))
      return false;
  }
  glm::dvec3 lo(scene.camera.position), hi(scene.camera.position);
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    ObjectRecord r;
    r.object = scene.objects[i];
    r.to_world = object_to_world(r.object.transform);
    r.to_object = glm::inverse(r.to_world);
    r.normal_to_world = glm::transpose(glm::inverse(glm::dmat3(r.to_world)));
    r.mask = r.object.material.type == MaterialType::kDielectric ? kDielectricMask : kOpaqueMask;
    glm::dvec3 olo, ohi;
    if (r.object.shape.type == ShapeType::kMesh) {
      const TriangleMesh& mesh = meshes[size_t(r.object.shape.mesh)].mesh;
      olo = ohi = mesh.positions[0];
      for (const glm::dvec3& p : mesh.positions) {
        olo = glm::min(olo, p);
        ohi = glm::max(ohi, p);
      }
    } else {
      shape_bounds(r.object.shape, olo, ohi);
    }
    // World bounds of the 8 transformed corners.
    r.world_lo = glm::dvec3(std::numeric_limits<double>::infinity());
    r.world_hi = -r.world_lo;
    for (int c = 0; c < 8; ++c) {
      const glm::dvec3 corner((c & 1) ? ohi.x : olo.x, (c & 2) ? ohi.y : olo.y,
                              (c & 4) ? ohi.z : olo.z);
      const glm::dvec3 w = glm::dvec3(r.to_world * glm::dvec4(corner, 1.0));
      r.world_lo = glm::min(r.world_lo, w);
      r.world_hi = glm::max(r.world_hi, w);
    }
    r.diagonal = glm::length(r.world_hi - r.world_lo);
    lo = glm::min(lo, r.world_lo);
    hi = glm::max(hi, r.world_hi);
    if (r.object.shape.type == ShapeType::kMesh) {
      RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(instance, meshes[size_t(r.object.shape.mesh)].scene);
      float m[16];
      for (int c = 0; c < 4; ++c) {
        for (int k = 0; k < 4; ++k)
          m[c * 4 + k] = float(r.to_world[c][k]);
      }
      rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, m);
      rtcSetGeometryMask(instance, r.mask);
      rtcCommitGeometry(instance);
      const unsigned id = rtcAttachGeometry(top, instance);
      rtcReleaseGeometry(instance);
      if (instance_to_object.size() <= id)
        instance_to_object.resize(id + 1, -1);
      instance_to_object[id] = int(i);
    } else {
      analytic.push_back(int(i));
    }
    objects.push_back(std::move(r));
  }
  if (!check_reach(scene, objects, error))
    return false;
  rtcCommitScene(top);
  if (const RTCError e = rtcGetDeviceError(device); e != RTC_ERROR_NONE) {
    error = scene.filename + ": Embree scene build failed (" + embree_error_text(e) + ")";
    return false;
  }
  extent = std::max(1e-3, glm::length(hi - lo));
  return true;
}

bool TracerScene::intersect(const TracerRay& ray, double t_max, unsigned mask,
                            SurfaceHit& hit) const {
  double best = t_max;
  int object = -1;
  unsigned prim = 0;
  float bu = 0.0f, bv = 0.0f;
  PrimitiveHit primitive;
  if (!instance_to_object.empty()) {
    RTCRayHit rh;
    init_rayhit(rh, glm::vec3(ray.origin), glm::vec3(ray.direction), 0.0f,
                float(std::min(t_max, double(gpu::GF_FAR))));
    rh.ray.mask = mask;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(top, &context, &rh);
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
      best = rh.ray.tfar;
      object = instance_to_object[rh.hit.instID[0]];
      prim = rh.hit.primID;
      bu = rh.hit.u;
      bv = rh.hit.v;
    }
  }
  bool analytic_hit = false;
  for (const int i : analytic) {
    const ObjectRecord& r = objects[size_t(i)];
    if (!(r.mask & mask) || !overlaps(ray, r.world_lo, r.world_hi, best))
      continue;
    const glm::dvec3 o(r.to_object * glm::dvec4(ray.origin, 1.0));
    const glm::dvec3 d(r.to_object * glm::dvec4(ray.direction, 0.0));
    PrimitiveHit h;
    if (intersect_shape(r.object.shape, o, d, 0.0, best, h)) {
      best = h.t;
      object = i;
      primitive = h;
      analytic_hit = true;
    }
  }
  if (object < 0)
    return false;
  const ObjectRecord& r = objects[size_t(object)];
  hit.t = best;
  hit.object = object;
  if (analytic_hit) {
    hit.position = ray.origin + best * ray.direction;
    hit.geometric_normal = glm::normalize(r.normal_to_world * primitive.normal);
    hit.shading_normal = hit.geometric_normal;
    hit.uv = primitive.uv;
    hit.epsilon = 1e-9 * (extent + glm::length(hit.position));
    return true;
  }
  const MeshRecord& m = meshes[size_t(r.object.shape.mesh)];
  const glm::ivec3 f = m.mesh.triangles[prim];
  const glm::dvec3 p0 = m.mesh.positions[size_t(f.x)], p1 = m.mesh.positions[size_t(f.y)],
                   p2 = m.mesh.positions[size_t(f.z)];
  const double u = bu, v = bv, w = 1.0 - u - v;
  hit.position = glm::dvec3(r.to_world * glm::dvec4(w * p0 + u * p1 + v * p2, 1.0));
  hit.geometric_normal =
      glm::normalize(r.normal_to_world * (m.orientation * glm::cross(p1 - p0, p2 - p0)));
  hit.shading_normal = hit.geometric_normal;
  if (r.object.shape.smooth_normals) {
    const glm::dvec3 n = w * m.vertex_normals[size_t(f.x)] + u * m.vertex_normals[size_t(f.y)] +
                         v * m.vertex_normals[size_t(f.z)];
    if (glm::length(n) > 0.0)
      hit.shading_normal = glm::normalize(r.normal_to_world * n);
  }
  hit.face = int(prim);
  hit.weights = glm::dvec3(w, u, v);
  hit.uv = glm::dvec2(uv_at(m.appearance, prim, hit.weights));
  // Embree works in float: step well past its intersection error, relative to the object's
  // size and to the magnitude of the coordinates.
  hit.epsilon = 1e-5 * (r.diagonal + glm::length(hit.position));
  return true;
}

TracerRay TracerScene::spawn(const SurfaceHit& hit, glm::dvec3 direction) {
  const double side = glm::dot(direction, hit.geometric_normal) >= 0.0 ? 1.0 : -1.0;
  return {hit.position + side * hit.epsilon * hit.geometric_normal, direction};
}

}  // namespace gfield
