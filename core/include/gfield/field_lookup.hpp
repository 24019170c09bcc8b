#pragma once
// CPU lookup of a geometry field: the first hit beyond the ray's origin (or the last hit) of any
// ray on an object stored as a geometry field (K layers of hits) + geometry image. The math is
// shaders/lib/field_lookup.glsl, compiled as C++, so that the runtime's GLSL gives the same answers
// (docs/geometry-field.md).

#include <array>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "gfield/geometry_field.hpp"
#include "gfield/geometry_image.hpp"
#include "gfield/gpu_contract.hpp"

namespace gfield {

/// How a ray is looked up (docs/geometry-field.md):
///  - kNearest: the uv stored for the nearest entry and exit samples (the paper, no filtering);
///  - kLinear: the paper's linear kernel over the 16 surrounding sample pairs;
///  - kRefined: the 16 pairs' uvs refined against the geometry image's surface by Newton's
///    method and verified against the ray; the nearest verified hit.
/// Each pair's uv is its first stored hit (over the K layers) beyond the ray's origin t_min;
/// refined goes on to the pair's next layers while a candidate fails to verify.
enum class LookupMode {
  kNearest = gpu::GF_MODE_NEAREST,
  kLinear = gpu::GF_MODE_LINEAR,
  kRefined = gpu::GF_MODE_REFINED
};

/// "nearest", "linear", "refined".
const char* lookup_mode_name(LookupMode mode);
/// Parses a name of lookup_mode_name; false for anything else.
bool parse_lookup_mode(const std::string& name, LookupMode& mode);

/// origin + t * direction, t in [t_min, t_max] (direction need not be unit).
struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};
  float t_min = 0.0f;
  float t_max = gpu::GF_FAR;
};

/// A lookup's answer. t is along the ray's own direction; distance = t * |direction|.
struct FieldHit {
  bool hit = false;
  float t = 0.0f;
  float distance = 0.0f;
  glm::vec2 uv{-1.0f};       ///< geometry-image uv
  glm::vec3 position{0.0f};  ///< coordinates of the ray (mesh, or world for instances)
  glm::vec3 normal{0.0f};    ///< unit normal, same coordinates
};

/// The work of CPU lookups, counted as the shaders count it (shaders/lib/work.glsl): counts[k] for
/// the contract's WORK_k (lookups, field and image texel fetches, Newton steps), so that a CPU
/// lookup's cost is the GPU's.
struct LookupWork {
  std::array<uint64_t, gpu::WORK_COUNT> counts{};
};

/// A geometry field with the geometry image it indexes. Holds pointers: both must outlive it.
struct FieldLookup {
  const GeometryField* field = nullptr;
  const GeometryImage* image = nullptr;
  int layers = 0;  ///< layers looked up: the first min(layers, K); 0: all K
  /// null, or where the lookups count their work (one thread at a time)
  LookupWork* work = nullptr;
};

/// Pairs a field with its image. False with an error when they do not belong together (different
/// box, source or build id), or when either is empty or inconsistent (table size, image size < 2).
bool make_field_lookup(const GeometryField& field, const GeometryImage& image, FieldLookup& lookup,
                       std::string& error);

/// False with an error for a ray with a non-finite origin or direction, a zero direction, or
/// t_min > t_max (NaN included). Lookups return a miss for such rays.
bool check_ray(const Ray& ray, std::string& error);

/// The first hit of `ray` (mesh coordinates) in [t_min, t_max]: beyond its origin t_min, also
/// when the origin lies inside the box behind parts of the surface (reached through the layers).
FieldHit lookup_first_hit(const FieldLookup& lookup, const Ray& ray, LookupMode mode);
/// The first hit of `ray` (mesh coordinates), a ray leaving the surface (its origin just off it),
/// as the runtime looks up the mesh a ray leaves (gf_trace_leaving of field_lookup.glsl, called
/// by shaders/lib/scene.glsl): the ray's own first hit where it lies beyond `self_t_min`; a nearer
/// one only where it faces the ray opposite to the start (`facing`: +1 for a ray leaving on the
/// side the surface's normals face, -1 on the other), else the lookup goes on beyond it; where
/// that does not settle it, the first hit beyond self_t_min of the parallel ray from
/// `self_origin` (the start moved farther off the surface, by the geometry image's ray offset),
/// in refined mode moved onto `ray` (a miss where that fails). `any_hit`: a shadow ray, any hit
/// in range will do: looked up on its side, and on either side where that lookup searched
/// without verifying a hit (gf_trace_from).
FieldHit lookup_first_hit_leaving(const FieldLookup& lookup, const Ray& ray, glm::vec3 self_origin,
                                  float self_t_min, float facing, LookupMode mode,
                                  bool any_hit = false);
/// The last hit of `ray` in [t_min, t_max]: the first hit of the reversed line, read from the
/// table with entry and exit swapped (rays leaving a refracting object).
FieldHit lookup_last_hit(const FieldLookup& lookup, const Ray& ray, LookupMode mode);

/// An instance: the object placed in the world by `object_to_world` (rigid, scaled, any
/// invertible affine map). The world ray is mapped into mesh coordinates first; the hit comes
/// back in world coordinates (normal by the inverse transpose), with t unchanged.
FieldHit lookup_instance(const FieldLookup& lookup, const glm::mat4& object_to_world,
                         const Ray& world_ray, LookupMode mode, bool last_hit = false);

}  // namespace gfield
