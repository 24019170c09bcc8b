#include "gfield/glass_displacement.hpp"

#include <cmath>

#include "gfield/glsl_names.hpp"
#include "gfield/gpu_contract.hpp"

// shaders/lib/glass_displacement.glsl compiled as C++ (outside namespace gfield, whose own
// refract/reflect would hide GLM's).
namespace gfield_glass_glsl {
using namespace gfield::glsl;  // the GLSL vocabulary of glass_displacement.glsl
using namespace gfield::gpu;   // and the contract's GF_FAR
#include "gfield/glsl_begin.hpp"

#include "../../shaders/lib/glass_displacement.glsl"

#include "gfield/glsl_end.hpp"
}  // namespace gfield_glass_glsl

namespace gfield {
namespace glass_glsl = gfield_glass_glsl;

float plate_incidence_sine(float x, float y, float thickness, float ior) {
  return glass_glsl::gd_plate_incidence_sine(x, y, thickness, ior);
}

glm::vec3 plate_displace(const GlassPlate& plate, glm::vec3 eye, glm::vec3 vertex) {
  return glass_glsl::gd_plate_displace(eye, vertex, plate.centre, glm::normalize(plate.normal),
                                       plate.thickness, plate.ior);
}

bool cylinder_displace(const GlassCylinder& cylinder, CylinderPath path, glm::vec3 eye,
                       glm::vec3 vertex, glm::vec3& seen) {
  bool ok = false;
  seen = glass_glsl::gd_cylinder_displace(int(path), cylinder.outer_radius, cylinder.inner_radius,
                                          cylinder.ior, eye, vertex, ok);
  return ok;
}

GlassPlate glass_plate(const SceneObject& object, int pair) {
  const glm::dmat4 to_world = object_to_world(object.transform);
  const int axis = pair == 0 ? 2 : pair - 1;
  const glm::dvec3 size(object.shape.size.x, object.shape.size.y, object.shape.thickness);
  glm::dvec4 offset(0.0);
  offset[axis] = 0.5 * size[axis];
  const glm::dvec3 front(to_world * (glm::dvec4(0.0, 0.0, 0.0, 1.0) + offset));
  const glm::dvec3 back(to_world * (glm::dvec4(0.0, 0.0, 0.0, 1.0) - offset));
  glm::dvec3 axis_vector(0.0);
  axis_vector[axis] = 1.0;
  const glm::dvec3 normal =
      glm::normalize(glm::transpose(glm::inverse(glm::dmat3(to_world))) * axis_vector);
  GlassPlate plate;
  plate.centre = glm::vec3(0.5 * (front + back));
  plate.normal = glm::vec3(normal);
  plate.thickness = float(std::abs(glm::dot(front - back, normal)));
  plate.ior = object.material.ior;
  return plate;
}

bool glass_cylinder(const SceneObject& object, GlassCylinder& cylinder, glm::mat4& to_world,
                    std::string& error) {
  const glm::vec3 s = glm::abs(object.transform.scale);
  if (std::abs(s.x - s.z) > 1e-6f * s.x) {
    error = object.name +
            ": a hollow cylinder seen by vertex displacement needs the same scale along X and Z";
    return false;
  }
  if (std::abs(s.x - s.y) > 1e-6f * s.x) {
    error = object.name + ": a hollow cylinder seen by vertex displacement needs a uniform scale";
    return false;
  }
  to_world = glm::mat4(object_to_world(object.transform));
  cylinder.outer_radius = object.shape.radius;
  cylinder.inner_radius = object.shape.radius - object.shape.thickness;
  cylinder.ior = object.material.ior;
  return true;
}

}  // namespace gfield
