// The reference ray tracer (see reference_tracer.hpp and docs/reference-tracer.md).

#include "preprocess/reference_tracer.hpp"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>

#include "geometry/analytic_primitives.hpp"
#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/outward_normals.hpp"
#include "gfield/environment.hpp"
#include "gfield/gpu_contract.hpp"
#include "gfield/limits.hpp"
#include "gfield/optics.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/embree_mesh.hpp"

namespace gfield {
namespace {

constexpr unsigned kOpaqueMask = 1u;      // diffuse and mirror objects: block shadow rays
constexpr unsigned kDielectricMask = 2u;  // dielectrics: transparent to shadow rays
constexpr unsigned kAllMask = kOpaqueMask | kDielectricMask;

/// splitmix64: the per-sample random numbers (a pure function of its input).
std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}
double unit_double(std::uint64_t x) {
  return double(x >> 11) * (1.0 / 9007199254740992.0);
}

struct MeshRecord {
  TriangleMesh mesh;
  MeshAppearance appearance;               ///< its own base colour (materials "texture": "mesh")
  std::vector<glm::dvec3> vertex_normals;  ///< angle-weighted, outward
  double orientation = 1.0;                ///< -1 when the file's winding points inwards
  RTCScene scene = nullptr;
};

struct ObjectRecord {
  SceneObject object;
  glm::dmat4 to_world{1.0};
  glm::dmat4 to_object{1.0};
  glm::dmat3 normal_to_world{1.0};  ///< inverse transpose of the linear part
  glm::dvec3 world_lo{0.0}, world_hi{0.0};
  double diagonal = 0.0;  ///< of the world bounds
  unsigned mask = kOpaqueMask;
};

struct SurfaceHit {
  double t = 0.0;
  int object = -1;
  glm::dvec3 position{0.0};
  glm::dvec3 geometric_normal{0.0};  ///< world, unit, outward
  glm::dvec3 shading_normal{0.0};    ///< world, unit, outward
  glm::dvec2 uv{0.0};
  int face = -1;            ///< mesh hits: the triangle
  glm::dvec3 weights{0.0};  ///< mesh hits: barycentric weights of its corners
  double epsilon = 0.0;     ///< offset for rays leaving this point
};

struct Counters {
  std::uint64_t secondary = 0;
  std::uint64_t shadow = 0;
};

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

bool parse_dielectric_mode(std::string_view name, DielectricMode& mode) {
  if (name == "full") {
    mode = DielectricMode::kFull;
  } else if (name == "refract-only") {
    mode = DielectricMode::kRefractOnly;
  } else if (name == "tir-only") {
    mode = DielectricMode::kTirOnly;
  } else {
    return false;
  }
  return true;
}

const char* dielectric_mode_name(DielectricMode mode) {
  switch (mode) {
    case DielectricMode::kFull:
      return "full";
    case DielectricMode::kRefractOnly:
      return "refract-only";
    case DielectricMode::kTirOnly:
      return "tir-only";
  }
  return "?";
}

InterfaceSplit split_at_interface(glm::dvec3 incident, glm::dvec3 normal, double n1, double n2,
                                  DielectricMode mode) {
  InterfaceSplit s;
  const double cos_i = std::clamp(-glm::dot(incident, normal), 0.0, 1.0);
  s.reflected = glm::normalize(reflect(incident, normal));
  const std::optional<glm::dvec3> t = refract(incident, normal, n1 / n2);
  s.total_internal_reflection = !t.has_value();
  if (t)
    s.transmitted = glm::normalize(*t);
  const double r = fresnel_dielectric(cos_i, n1, n2);
  switch (mode) {
    case DielectricMode::kFull:
      s.reflected_weight = s.total_internal_reflection ? 1.0 : r;
      s.transmitted_weight = s.total_internal_reflection ? 0.0 : 1.0 - r;
      break;
    case DielectricMode::kRefractOnly:
      s.transmitted_weight = s.total_internal_reflection ? 0.0 : 1.0;
      break;
    case DielectricMode::kTirOnly:
      s.reflected_weight = s.total_internal_reflection ? 1.0 : 0.0;
      s.transmitted_weight = s.total_internal_reflection ? 0.0 : 1.0;
      break;
  }
  return s;
}

RenderBudget estimate_render(int width, int height, int samples_per_pixel) {
  RenderBudget b;
  b.image_bytes = double(width) * double(height) * double(sizeof(glm::vec3));
  b.camera_samples = double(width) * double(height) * double(samples_per_pixel);
  b.estimated_seconds = b.camera_samples * 3.0 / kEstimatedRaysPerSecond;
  return b;
}

namespace {

std::string human_seconds(double s) {
  char buffer[64];
  if (s < 120.0) {
    std::snprintf(buffer, sizeof(buffer), "%.0f s", s);
  } else if (s < 7200.0) {
    std::snprintf(buffer, sizeof(buffer), "%.0f min", s / 60.0);
  } else {
    std::snprintf(buffer, sizeof(buffer), "%.1f h", s / 3600.0);
  }
  return buffer;
}

}  // namespace

bool check_render_budget(int width, int height, int samples_per_pixel, std::string& error) {
  const RenderBudget budget = estimate_render(width, height, samples_per_pixel);
  if (budget.image_bytes <= kMaxImageBytes && budget.camera_samples <= kMaxCameraSamples &&
      width <= 65536 && height <= 65536) {
    return true;
  }
  char message[512];
  std::snprintf(message, sizeof(message),
                "refusing %dx%d at %d spp: %.3g camera samples (limit %.3g), image %.2f GB "
                "(limit %.1f GB), estimated %s on this machine",
                width, height, samples_per_pixel, budget.camera_samples, kMaxCameraSamples,
                budget.image_bytes / 1e9, kMaxImageBytes / 1e9,
                human_seconds(budget.estimated_seconds).c_str());
  error = message;
  return false;
}

struct ReferenceTracer::Impl {
  Scene scene;
  Environment environment;
  std::vector<MeshRecord> meshes;
  std::vector<ObjectRecord> objects;
  std::vector<int> analytic;            ///< indices of analytic objects
  std::vector<int> instance_to_object;  ///< Embree geometry ID -> object
  RTCDevice device = nullptr;
  RTCScene top = nullptr;
  double extent = 1.0;  ///< scene diagonal, for ray offsets

  ~Impl() {
    for (MeshRecord& m : meshes) {
      if (m.scene)
        rtcReleaseScene(m.scene);
    }
    if (top)
      rtcReleaseScene(top);
    if (device)
      rtcReleaseDevice(device);
  }

  bool build_mesh(MeshRecord& record, const MeshAsset& asset, std::string& error) {
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
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), mesh.triangles.size()));
    if (!vertices || !indices) {
      rtcReleaseGeometry(geometry);
      error = file + ": Embree cannot allocate the mesh buffers";
      return false;
    }
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      for (int k = 0; k < 3; ++k)
        vertices[3 * v + size_t(k)] = float(mesh.positions[v][k]);
    }
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
      for (int k = 0; k < 3; ++k)
        indices[3 * f + size_t(k)] = unsigned(mesh.triangles[f][k]);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(record.scene, geometry, 0);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(record.scene);
    return true;
  }

  bool build(const Scene& input, std::string& error) {
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

  /// Nearest hit in (0, t_max) among objects whose mask meets `mask`.
  bool intersect(const TracerRay& ray, double t_max, unsigned mask, SurfaceHit& hit) const {
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

  /// A ray leaving `hit` in `direction`, offset to the side of the surface it goes to.
  static TracerRay spawn(const SurfaceHit& hit, glm::dvec3 direction) {
    const double side = glm::dot(direction, hit.geometric_normal) >= 0.0 ? 1.0 : -1.0;
    return {hit.position + side * hit.epsilon * hit.geometric_normal, direction};
  }

  /// The albedo at a diffuse hit: the material's texture, or its colour times the mesh's own
  /// base colour there (exact: the mesh's texture looked up at the hit's uv).
  glm::dvec3 albedo_at(const SurfaceHit& hit) const {
    const SceneObject& object = objects[size_t(hit.object)].object;
    glm::dvec3 albedo(texture_albedo(object.material, glm::vec2(hit.uv)));
    if (object.material.texture == TextureType::kMesh && hit.face >= 0) {
      const MeshRecord& m = meshes[size_t(object.shape.mesh)];
      albedo *= glm::dvec3(base_color_at(m.mesh, m.appearance, size_t(hit.face), hit.weights));
    }
    return albedo;
  }

  glm::dvec3 shade_diffuse(const SurfaceHit& hit, glm::dvec3 incoming, Counters& counters) const {
    const glm::dvec3 albedo = albedo_at(hit);
    // Two-sided: the normal facing the viewer.
    const double facing = glm::dot(incoming, hit.geometric_normal) < 0.0 ? 1.0 : -1.0;
    const glm::dvec3 n = facing * hit.shading_normal;
    glm::dvec3 light_sum(scene.ambient);
    for (const Light& light : scene.lights) {
      glm::dvec3 l;
      double distance;
      if (light.type == LightType::kDirectional) {
        l = -glm::dvec3(light.direction);
        distance = std::numeric_limits<double>::infinity();
      } else {
        l = glm::dvec3(light.position) - hit.position;
        distance = glm::length(l);
        if (distance <= 0.0)
          continue;
        l /= distance;
      }
      const double cosine = glm::dot(n, l);
      if (cosine <= 0.0 || glm::dot(l, facing * hit.geometric_normal) <= 0.0)
        continue;
      ++counters.shadow;
      SurfaceHit blocker;
      const TracerRay shadow = spawn(hit, l);
      if (intersect(shadow, std::isinf(distance) ? 1e30 : distance, kOpaqueMask, blocker)) {
        continue;
      }
      const double falloff = std::isinf(distance) ? 1.0 : 1.0 / (distance * distance);
      light_sum += glm::dvec3(light.color) * double(light.intensity) * cosine * falloff;
    }
    return albedo * light_sum;
  }

  glm::dvec3 radiance(const TracerRay& ray, int depth, double weight, const RenderOptions& options,
                      Counters& counters) const {
    SurfaceHit hit;
    if (!intersect(ray, std::numeric_limits<double>::infinity(), kAllMask, hit)) {
      return glm::dvec3(environment_radiance(environment, glm::vec3(ray.direction)));
    }
    const Material& material = objects[size_t(hit.object)].object.material;
    const glm::dvec3 d = ray.direction;
    const bool front = glm::dot(d, hit.geometric_normal) < 0.0;
    const glm::dvec3 n = front ? hit.shading_normal : -hit.shading_normal;
    switch (material.type) {
      case MaterialType::kDiffuse:
        return shade_diffuse(hit, d, counters);
      case MaterialType::kMirror: {
        if (depth >= options.max_depth)
          return glm::dvec3(0.0);
        glm::dvec3 r = glm::normalize(reflect(d, n));
        if (glm::dot(r, front ? hit.geometric_normal : -hit.geometric_normal) <= 0.0) {
          // An interpolated normal can send the reflection into the surface: use the face's.
          const glm::dvec3 g = front ? hit.geometric_normal : -hit.geometric_normal;
          r = glm::normalize(reflect(d, g));
        }
        ++counters.secondary;
        const glm::dvec3 tint(material.color);
        return tint * radiance(spawn(hit, r), depth + 1, weight, options, counters);
      }
      case MaterialType::kDielectric: {
        // Outside every dielectric is air (index 1); the segment just travelled was inside the
        // object when we hit its surface from the back.
        glm::dvec3 attenuation(1.0);
        if (!front)
          attenuation = glm::exp(-glm::dvec3(material.absorption) * hit.t);
        if (depth >= options.max_depth)
          return glm::dvec3(0.0);
        const double n1 = front ? 1.0 : material.ior;
        const double n2 = front ? material.ior : 1.0;
        const InterfaceSplit split = split_at_interface(d, n, n1, n2, options.dielectric);
        glm::dvec3 sum(0.0);
        const bool prune = options.dielectric == DielectricMode::kFull;
        if (split.reflected_weight > 0.0 &&
            (!prune || weight * split.reflected_weight >= options.min_weight)) {
          ++counters.secondary;
          sum +=
              split.reflected_weight * radiance(spawn(hit, split.reflected), depth + 1,
                                                weight * split.reflected_weight, options, counters);
        }
        if (split.transmitted_weight > 0.0 &&
            (!prune || weight * split.transmitted_weight >= options.min_weight)) {
          ++counters.secondary;
          sum += split.transmitted_weight * radiance(spawn(hit, split.transmitted), depth + 1,
                                                     weight * split.transmitted_weight, options,
                                                     counters);
        }
        return attenuation * sum;
      }
    }
    return glm::dvec3(0.0);
  }
};

ReferenceTracer::ReferenceTracer() = default;
ReferenceTracer::~ReferenceTracer() = default;

bool ReferenceTracer::build(const Scene& scene, std::string& error) {
  auto impl = std::make_unique<Impl>();
  if (!impl->build(scene, error))
    return false;
  impl_ = std::move(impl);
  return true;
}

const Scene& ReferenceTracer::scene() const {
  return impl_->scene;
}

glm::dvec3 ReferenceTracer::trace(const TracerRay& ray, const RenderOptions& options) const {
  Counters counters;
  return impl_->radiance(ray, 0, 1.0, options, counters);
}

std::vector<PathEvent> ReferenceTracer::follow_path(const TracerRay& start, int max_events) const {
  std::vector<PathEvent> events;
  TracerRay ray = start;
  for (int k = 0; k < max_events; ++k) {
    SurfaceHit hit;
    if (!impl_->intersect(ray, std::numeric_limits<double>::infinity(), kAllMask, hit)) {
      events.push_back({PathEvent::kEscape, -1, ray.origin, ray.direction});
      return events;
    }
    const Material& material = impl_->objects[size_t(hit.object)].object.material;
    const bool front = glm::dot(ray.direction, hit.geometric_normal) < 0.0;
    const glm::dvec3 n = front ? hit.shading_normal : -hit.shading_normal;
    PathEvent e;
    e.object = hit.object;
    e.position = hit.position;
    if (material.type == MaterialType::kDiffuse) {
      e.kind = PathEvent::kDiffuse;
      e.direction = ray.direction;
      events.push_back(e);
      return events;
    }
    if (material.type == MaterialType::kMirror) {
      e.kind = PathEvent::kMirror;
      e.direction = glm::normalize(reflect(ray.direction, n));
    } else {
      const double n1 = front ? 1.0 : material.ior, n2 = front ? material.ior : 1.0;
      const InterfaceSplit s =
          split_at_interface(ray.direction, n, n1, n2, DielectricMode::kTirOnly);
      e.kind = s.total_internal_reflection ? PathEvent::kTotalInternalReflection
               : front                     ? PathEvent::kEnter
                                           : PathEvent::kExit;
      e.direction = s.total_internal_reflection ? s.reflected : s.transmitted;
    }
    events.push_back(e);
    ray = Impl::spawn(hit, e.direction);
  }
  return events;
}

namespace {

/// Strata grid nx x ny = spp with nx the largest divisor <= sqrt(spp).
glm::ivec2 strata(int spp) {
  int nx = std::max(1, int(std::sqrt(double(spp))));
  while (spp % nx != 0)
    --nx;
  return {nx, spp / nx};
}

/// Sample position inside pixel (x, y) for sample s.
glm::dvec2 sample_position(int x, int y, int s, int width, glm::ivec2 grid,
                           const RenderOptions& options) {
  const int sx = s % grid.x, sy = s / grid.x;
  double jx = 0.5, jy = 0.5;
  if (options.jitter) {
    const std::uint64_t key = mix64(
        options.seed ^ mix64((std::uint64_t(y) * std::uint64_t(width) + std::uint64_t(x)) * 1024u +
                             std::uint64_t(s)));
    jx = unit_double(key);
    jy = unit_double(mix64(key));
  }
  return {double(x) + (double(sx) + jx) / double(grid.x),
          double(y) + (double(sy) + jy) / double(grid.y)};
}

class Progress {
 public:
  Progress(bool enabled, int total) : enabled_(enabled), total_(total) {}
  /// One more row done; returns the rows done.
  int step() {
    const int done = ++done_;
    if (!enabled_)
      return done;
    const int percent = done * 100 / total_;
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || percent == shown_)
      return done;
    shown_ = percent;
    const int bar = percent * 40 / 100;
    std::fprintf(stderr, "\rrender [%.*s%*s] %3d%%", bar,
                 "########################################", 40 - bar, "", percent);
    if (done == total_)
      std::fprintf(stderr, "\n");
    std::fflush(stderr);
    return done;
  }

 private:
  bool enabled_;
  int total_;
  std::atomic<int> done_{0};
  std::mutex mutex_;
  int shown_ = -1;
};

}  // namespace

Image ReferenceTracer::render(const RenderOptions& options, RenderStats* stats) const {
  const Scene& scene = impl_->scene;
  const int width = options.width > 0 ? options.width : scene.width;
  const int height = options.height > 0 ? options.height : scene.height;
  const int spp = std::max(1, options.samples_per_pixel);
  const glm::ivec2 grid = strata(spp);
  Image image(width, height);
  std::atomic<std::uint64_t> secondary{0}, shadow{0};
  Progress progress(options.progress, height);
  Stopwatch watch;
  tbb::parallel_for(
      tbb::blocked_range<int>(0, height, 1), [&](const tbb::blocked_range<int>& rows) {
        Counters counters;
        for (int y = rows.begin(); y < rows.end() && !stop_requested(options.control); ++y) {
          for (int x = 0; x < width; ++x) {
            glm::dvec3 sum(0.0);
            for (int s = 0; s < spp; ++s) {
              const CameraRay c = camera_ray(scene.camera, width, height,
                                             sample_position(x, y, s, width, grid, options));
              sum += impl_->radiance({c.origin, c.direction}, 0, 1.0, options, counters);
            }
            image.at(x, y) = glm::vec3(sum / double(spp));
          }
          report_progress(options.control, "render", double(progress.step()) / double(height));
        }
        secondary += counters.secondary;
        shadow += counters.shadow;
      });
  if (stats) {
    stats->seconds = watch.seconds();
    stats->camera_rays = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(spp);
    stats->secondary_rays = secondary;
    stats->shadow_rays = shadow;
  }
  return image;
}

RenderStats ReferenceTracer::cast_camera_rays(const RenderOptions& options) const {
  const Scene& scene = impl_->scene;
  const int width = options.width > 0 ? options.width : scene.width;
  const int height = options.height > 0 ? options.height : scene.height;
  const int spp = std::max(1, options.samples_per_pixel);
  const glm::ivec2 grid = strata(spp);
  std::atomic<std::uint64_t> hits{0};
  Stopwatch watch;
  tbb::parallel_for(
      tbb::blocked_range<int>(0, height, 1), [&](const tbb::blocked_range<int>& rows) {
        std::uint64_t local = 0;
        for (int y = rows.begin(); y < rows.end(); ++y) {
          for (int x = 0; x < width; ++x) {
            for (int s = 0; s < spp; ++s) {
              const CameraRay c = camera_ray(scene.camera, width, height,
                                             sample_position(x, y, s, width, grid, options));
              SurfaceHit hit;
              local += impl_->intersect({c.origin, c.direction},
                                        std::numeric_limits<double>::infinity(), kAllMask, hit);
            }
          }
        }
        hits += local;
      });
  RenderStats stats;
  stats.seconds = watch.seconds();
  stats.camera_rays = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(spp);
  return stats;
}

}  // namespace gfield
