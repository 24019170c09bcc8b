// Analytic ray-shape intersections: shaders/lib/shapes.glsl, the GPU's, compiled in double.

#include "geometry/analytic_primitives.hpp"

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "gfield/glsl_names.hpp"
#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {
namespace shapes_glsl {

using namespace gfield::glsl;  // the GLSL vocabulary of shapes.glsl
using namespace gfield::gpu;   // and the contract's codes and GF_FAR
// shapes.glsl's types in double precision, and the contract's pi in that precision.
using real = double;
using rvec2 = dvec2;
using rvec3 = dvec3;
using rvec4 = dvec4;
constexpr real GF_PI = glm::pi<real>();

#include "gfield/glsl_begin.hpp"

#include "../shaders/lib/shapes.glsl"

#include "gfield/glsl_end.hpp"

}  // namespace shapes_glsl
}  // namespace

bool intersect_shape(const Shape& shape, glm::dvec3 origin, glm::dvec3 direction, double t_min,
                     double t_max, PrimitiveHit& hit) {
  const shapes_glsl::ShapeHit h = shapes_glsl::intersect_shape(
      int(shape.type), glm::dvec4(shape.radius, shape.height, shape.thickness, 0.0),
      glm::dvec3(shape.size), origin, direction, t_min, t_max);
  if (!h.hit)
    return false;
  hit.t = h.t;
  hit.normal = h.normal;
  hit.uv = h.uv;
  return true;
}

}  // namespace gfield
