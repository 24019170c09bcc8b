#include "gfield/field_lookup.hpp"

#include <algorithm>
#include <cmath>

#include "gfield/build_id.hpp"
#include "gfield/check.hpp"
#include "gfield/glsl_names.hpp"
#include "gfield/gpu_contract.hpp"
#include "gfield/printable.hpp"
#include "glsl_field_tables.hpp"

namespace gfield {
namespace {

using namespace gfield::glsl;  // the GLSL vocabulary of field_lookup.glsl
using namespace gfield::gpu;   // and the contract's field addressing (field_lines.glsl)

/// shaders/lib/field_lookup.glsl compiled as C++: its functions become members of this struct,
/// whose fetch functions read the CPU copies of the textures.
struct GlslFieldLookup : GlslFieldTables {
  const GeometryImage& image;
  int layers;

  int gf_field_layers() const { return layers; }
  int gf_image_size() const { return image.size; }
  vec4 gf_image_texel(int i, int j) const {
    count_work(WORK_IMAGE_FETCHES, 1);
    const size_t k = texel_index(image, i, j);
    return vec4(image.position[k], image.coverage[k]);
  }
  vec3 gf_image_normal_texel(int i, int j) const {
    count_work(WORK_IMAGE_FETCHES, 1);
    return image.normal[texel_index(image, i, j)];
  }
  vec3 gf_box_min() const { return field.box.min; }
  vec3 gf_box_max() const { return field.box.max; }

#include "gfield/glsl_begin.hpp"

#define GF_COUNT(kind, n) count_work(kind, n)  // field_lookup.glsl's hook, undefined at its end
#include "../../shaders/lib/field_lines.glsl"
#include "../../shaders/lib/field_lookup.glsl"

#include "gfield/glsl_end.hpp"
};

bool same_box(const Box& a, const Box& b) {
  const float tolerance = 1e-6f * diagonal(a);
  return all(lessThanEqual(abs(a.min - b.min), vec3(tolerance))) &&
         all(lessThanEqual(abs(a.max - b.max), vec3(tolerance)));
}

/// The lookup's GLSL functions over its field (limited to `layers`) and image.
GlslFieldLookup glsl_lookup(const FieldLookup& lookup) {
  const int layers =
      lookup.layers > 0 ? std::min(lookup.layers, lookup.field->layers) : lookup.field->layers;
  return {{*lookup.field, lookup.work}, *lookup.image, layers};
}

/// Whether `lookup` can look `ray` up (a miss otherwise).
bool can_look_up(const FieldLookup& lookup, const Ray& ray) {
  std::string error;
  return lookup.field != nullptr && lookup.image != nullptr && check_ray(ray, error);
}

/// A GLSL hit of `ray` as a FieldHit.
FieldHit field_hit(const GlslFieldLookup::GfHit& h, const Ray& ray) {
  FieldHit hit;
  if (h.hit) {
    hit.hit = true;
    hit.t = h.t;
    hit.distance = h.t * length(ray.direction);
    hit.uv = h.uv;
    hit.position = h.position;
    hit.normal = h.normal;
  }
  return hit;
}

FieldHit trace(const FieldLookup& lookup, const Ray& ray, LookupMode mode, bool last) {
  if (!can_look_up(lookup, ray)) {
    return {};
  }
  return field_hit(glsl_lookup(lookup).gf_trace(ray.origin, ray.direction, ray.t_min, ray.t_max,
                                                int(mode), last),
                   ray);
}

}  // namespace

const char* lookup_mode_name(LookupMode mode) {
  switch (mode) {
    case LookupMode::kNearest:
      return "nearest";
    case LookupMode::kLinear:
      return "linear";
    case LookupMode::kRefined:
      return "refined";
  }
  return "unknown";
}

bool parse_lookup_mode(const std::string& name, LookupMode& mode) {
  for (LookupMode m : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
    if (name == lookup_mode_name(m)) {
      mode = m;
      return true;
    }
  }
  return false;
}

bool make_field_lookup(const GeometryField& field, const GeometryImage& image, FieldLookup& lookup,
                       std::string& error) {
  if (field.samples_per_side <= 0 || field.layers < 1 || field.layers > kMaxLineHits ||
      field.nearest.size() != field_nearest_size(field) ||
      field.lines.size() < size_t(gpu::gf_field_tiles(field.samples_per_side))) {
    error =
        "geometry field: no nearest-hit table of 6N^2 x 5N^2 entries or no line table, or "
        "layers K outside [1, " +
        std::to_string(kMaxLineHits) + "]";
    return false;
  }
  const size_t texels = size_t(image.size) * size_t(image.size);
  if (image.size < 2 || image.position.size() != texels || image.normal.size() != texels ||
      image.coverage.size() != texels) {
    error = "geometry image: empty or inconsistent texel arrays";
    return false;
  }
  if (!same_box(field.box, image.box)) {
    error = "the geometry field and the geometry image have different boxes (not built together)";
    return false;
  }
  if (field.source != image.source) {
    error = "the geometry field was built from '" + printable(field.source) +
            "' but the geometry image from '" + printable(image.source) + "'";
    return false;
  }
  if (!check_same_build("the geometry field", field.build_id, "the geometry image", image.build_id,
                        error)) {
    return false;
  }
  lookup.field = &field;
  lookup.image = &image;
  return true;
}

bool check_ray(const Ray& ray, std::string& error) {
  const auto finite = [](vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  if (!finite(ray.origin) || !finite(ray.direction)) {
    error = "ray with a non-finite origin or direction";
    return false;
  }
  if (dot(ray.direction, ray.direction) == 0.0f) {
    error = "ray with a zero direction";
    return false;
  }
  if (!(ray.t_min <= ray.t_max)) {
    error = "ray with t_min > t_max or a NaN range";
    return false;
  }
  return true;
}

FieldHit lookup_first_hit(const FieldLookup& lookup, const Ray& ray, LookupMode mode) {
  return trace(lookup, ray, mode, false);
}

FieldHit lookup_first_hit_leaving(const FieldLookup& lookup, const Ray& ray, vec3 self_origin,
                                  float self_t_min, float facing, LookupMode mode, bool any_hit) {
  if (!can_look_up(lookup, ray)) {
    return {};
  }
  return field_hit(
      glsl_lookup(lookup).gf_trace_leaving(ray.origin, ray.direction, ray.t_min, ray.t_max,
                                           self_origin, self_t_min, facing, int(mode), any_hit),
      ray);
}

FieldHit lookup_last_hit(const FieldLookup& lookup, const Ray& ray, LookupMode mode) {
  return trace(lookup, ray, mode, true);
}

FieldHit lookup_instance(const FieldLookup& lookup, const glm::mat4& object_to_world,
                         const Ray& world_ray, LookupMode mode, bool last_hit) {
  const mat4 world_to_object = inverse(object_to_world);
  Ray ray = world_ray;
  ray.origin = vec3(world_to_object * vec4(world_ray.origin, 1.0f));
  ray.direction = vec3(world_to_object * vec4(world_ray.direction, 0.0f));
  FieldHit hit = trace(lookup, ray, mode, last_hit);
  if (hit.hit) {
    hit.position = vec3(object_to_world * vec4(hit.position, 1.0f));
    hit.normal = normalize(vec3(transpose(world_to_object) * vec4(hit.normal, 0.0f)));
    hit.distance = hit.t * length(world_ray.direction);
  }
  return hit;
}

}  // namespace gfield
