#pragma once
// Exact ray intersections with the analytic shapes of a scene (sphere, quad, box, cylinder,
// slab, hollow cylinder) in their object space, in double precision: the shaders' own
// shaders/lib/shapes.glsl compiled in double. Shapes as in gfield/scene.hpp: centred on the
// origin, cylinders along Y, quads and slabs facing +Z.

#include <glm/glm.hpp>

#include "gfield/scene.hpp"

namespace gfield {

/// A surface point of a shape, object space.
struct PrimitiveHit {
  double t = 0.0;          ///< along the ray's (unnormalised) direction
  glm::dvec3 normal{0.0};  ///< unit; points out of the solid (quads: +Z)
  glm::dvec2 uv{0.0};      ///< texture coordinates in [0,1]^2 (docs/scenes.md)
};

/// The nearest hit with t in (t_min, t_max) of origin + t * direction, or false. Meshes are not
/// analytic: false.
bool intersect_shape(const Shape& shape, glm::dvec3 origin, glm::dvec3 direction, double t_min,
                     double t_max, PrimitiveHit& hit);

}  // namespace gfield
