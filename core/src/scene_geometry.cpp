// Scene geometry: shape names and bounds, object transforms, the camera's rays.

#include "gfield/scene.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace gfield {

bool shape_is_closed(ShapeType type) {
  return type != ShapeType::kQuad;
}

const char* shape_name(ShapeType type) {
  switch (type) {
    case ShapeType::kMesh:
      return "mesh";
    case ShapeType::kSphere:
      return "sphere";
    case ShapeType::kQuad:
      return "quad";
    case ShapeType::kBox:
      return "box";
    case ShapeType::kCylinder:
      return "cylinder";
    case ShapeType::kSlab:
      return "slab";
    case ShapeType::kHollowCylinder:
      return "hollow-cylinder";
  }
  return "?";
}

CameraRay camera_ray(const Camera& camera, int width, int height, glm::dvec2 pixel) {
  const glm::dvec3 position(camera.position);
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tan_half = std::tan(glm::radians(double(camera.fov_degrees)) * 0.5);
  const double aspect = double(width) / double(height);
  const double sx = (2.0 * pixel.x / double(width) - 1.0) * tan_half * aspect;
  const double sy = (1.0 - 2.0 * pixel.y / double(height)) * tan_half;
  return {position, glm::normalize(forward + sx * right + sy * up)};
}

glm::dmat4 object_to_world(const Transform& transform) {
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(transform.translate));
  m = glm::rotate(m, glm::radians(double(transform.rotate_degrees.z)), glm::dvec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(double(transform.rotate_degrees.y)), glm::dvec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(double(transform.rotate_degrees.x)), glm::dvec3(1, 0, 0));
  return glm::scale(m, glm::dvec3(transform.scale));
}

bool transform_from_matrix(const glm::dmat4& matrix, Transform& transform, double& residual) {
  const glm::dmat3 linear(matrix);
  if (!(glm::determinant(linear) > 0.0)) {
    return false;
  }
  // Scale = column lengths; rotation = the columns orthonormalised (Gram-Schmidt), so that a
  // shear shows as a residual instead of a rotation that is not one.
  glm::dvec3 scale(glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2]));
  glm::dmat3 rotation;
  rotation[0] = linear[0] / scale.x;
  rotation[1] = glm::normalize(linear[1] - glm::dot(linear[1], rotation[0]) * rotation[0]);
  rotation[2] = glm::cross(rotation[0], rotation[1]);
  // R = Rz(z) Ry(y) Rx(x); element (row, column) is rotation[column][row].
  const double sy = std::clamp(-rotation[0][2], -1.0, 1.0);
  glm::dvec3 angles(0.0, std::asin(sy), 0.0);
  if (std::abs(sy) < 1.0 - 1e-12) {
    angles.x = std::atan2(rotation[1][2], rotation[2][2]);
    angles.z = std::atan2(rotation[0][1], rotation[0][0]);
  } else {
    angles.z = std::atan2(-rotation[1][0], rotation[1][1]);
  }
  transform.translate = glm::vec3(matrix[3]);
  transform.rotate_degrees = glm::vec3(glm::degrees(angles));
  transform.scale = glm::vec3(scale);
  const glm::dmat3 recomposed(object_to_world(transform));
  residual = 0.0;
  for (int c = 0; c < 3; ++c) {
    residual = std::max(residual, glm::length(recomposed[c] - linear[c]));
  }
  residual /= std::max({scale.x, scale.y, scale.z});
  return true;
}

void shape_bounds(const Shape& shape, glm::dvec3& lo, glm::dvec3& hi) {
  glm::dvec3 half(0.0);
  switch (shape.type) {
    case ShapeType::kMesh:
      break;
    case ShapeType::kSphere:
      half = glm::dvec3(shape.radius);
      break;
    case ShapeType::kQuad:
      half = glm::dvec3(0.5 * shape.size.x, 0.5 * shape.size.y, 0.0);
      break;
    case ShapeType::kBox:
      half = 0.5 * glm::dvec3(shape.size);
      break;
    case ShapeType::kSlab:
      half = 0.5 * glm::dvec3(shape.size.x, shape.size.y, shape.thickness);
      break;
    case ShapeType::kCylinder:
    case ShapeType::kHollowCylinder:
      half = glm::dvec3(shape.radius, 0.5 * shape.height, shape.radius);
      break;
  }
  lo = -half;
  hi = half;
}

double box_reach(const glm::dmat4& m, glm::dvec3 lo, glm::dvec3 hi) {
  double reach = 0.0;
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    const glm::dvec3 w = glm::dvec3(m * glm::dvec4(corner, 1.0));
    reach = std::max({reach, std::abs(w.x), std::abs(w.y), std::abs(w.z)});
  }
  return reach;
}

}  // namespace gfield
