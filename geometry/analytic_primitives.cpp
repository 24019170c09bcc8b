// Analytic ray-shape intersections: shaders/lib/shapes.glsl, the GPU's, compiled in double.

#include "geometry/analytic_primitives.hpp"

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {
namespace glsl {

using namespace glm;          // the GLSL vocabulary of shapes.glsl
using namespace gfield::gpu;  // and the contract's codes and GF_FAR
// shapes.glsl's types in double precision, and the contract's pi in that precision.
using real = double;
using rvec2 = dvec2;
using rvec3 = dvec3;
using rvec4 = dvec4;
constexpr real GF_PI = glm::pi<real>();

#include "../shaders/lib/shapes.glsl"

}  // namespace glsl
}  // namespace

bool intersect_shape(const Shape& shape, glm::dvec3 origin, glm::dvec3 direction, double t_min,
                     double t_max, PrimitiveHit& hit) {
  const glsl::ShapeHit h = glsl::intersect_shape(
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
