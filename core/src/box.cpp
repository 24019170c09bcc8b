#include "gfield/box.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtx/compatibility.hpp>
#include <limits>

namespace gfield {

namespace {

// Axis of a face, and the two axes its (s, t) coordinates follow (DESIGN.md: X faces (y, z),
// Y faces (x, z), Z faces (x, y)).
constexpr int kFaceAxis[6] = {0, 0, 1, 1, 2, 2};
constexpr int kFaceS[6] = {1, 1, 0, 0, 0, 0};
constexpr int kFaceT[6] = {2, 2, 2, 2, 1, 1};

glm::vec3 extent(const Box& box) {
  return box.max - box.min;
}

}  // namespace

glm::vec3 to_unit_cube(const Box& box, glm::vec3 p) {
  const glm::vec3 e = extent(box);
  glm::vec3 u;
  for (int k = 0; k < 3; ++k) {
    u[k] = e[k] > 0.0f ? (p[k] - box.min[k]) / e[k] : 0.5f;
  }
  return u;
}

glm::vec3 from_unit_cube(const Box& box, glm::vec3 u) {
  return box.min + u * extent(box);
}

glm::vec3 direction_to_unit_cube(const Box& box, glm::vec3 d) {
  return d / extent(box);
}

float diagonal(const Box& box) {
  return glm::length(extent(box));
}

Box padded_bounds(const glm::vec3* points, size_t count, float relative_padding) {
  Box box{glm::vec3(std::numeric_limits<float>::max()),
          glm::vec3(std::numeric_limits<float>::lowest())};
  for (size_t i = 0; i < count; ++i) {
    box.min = glm::min(box.min, points[i]);
    box.max = glm::max(box.max, points[i]);
  }
  if (count == 0) {
    return Box{};
  }
  const float diag = diagonal(box);
  const float pad = relative_padding * (diag > 0.0f ? diag : 1.0f);
  box.min -= glm::vec3(pad);
  box.max += glm::vec3(pad);
  return box;
}

glm::vec3 face_point(int face, glm::vec2 st) {
  glm::vec3 p;
  p[kFaceAxis[face]] = float(face & 1);
  p[kFaceS[face]] = st.x;
  p[kFaceT[face]] = st.y;
  return p;
}

glm::vec2 face_coords(int face, glm::vec3 p) {
  return {p[kFaceS[face]], p[kFaceT[face]]};
}

glm::vec3 sample_point(FaceSample s, int n) {
  return face_point(s.face, (glm::vec2(s.a, s.b) + 0.5f) / float(n));
}

FaceSample nearest_sample(int face, glm::vec2 st, int n) {
  const glm::vec2 c = glm::round(sample_coords(st, n));
  return {face, std::clamp(int(c.x), 0, n - 1), std::clamp(int(c.y), 0, n - 1)};
}

CubeCrossing clip_to_unit_cube(glm::vec3 origin, glm::vec3 direction) {
  CubeCrossing c;
  if (!(glm::all(glm::isfinite(origin)) && glm::all(glm::isfinite(direction))) ||
      glm::dot(direction, direction) == 0.0f) {
    return c;
  }
  float t0 = -std::numeric_limits<float>::infinity();
  float t1 = std::numeric_limits<float>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (direction[k] == 0.0f) {
      if (origin[k] < 0.0f || origin[k] > 1.0f) {
        return c;
      }
      continue;
    }
    const float inv = 1.0f / direction[k];
    float near = (0.0f - origin[k]) * inv;
    float far = (1.0f - origin[k]) * inv;
    // Entering through the low face when travelling in +k, through the high face otherwise.
    int near_face = 2 * k + (direction[k] > 0.0f ? 0 : 1);
    int far_face = 2 * k + (direction[k] > 0.0f ? 1 : 0);
    if (near > far) {
      std::swap(near, far);
    }
    if (near > t0) {
      t0 = near;
      c.entry_face = near_face;
    }
    if (far < t1) {
      t1 = far;
      c.exit_face = far_face;
    }
  }
  if (!(t0 < t1)) {
    return c;
  }
  c.hit = true;
  c.t_entry = t0;
  c.t_exit = t1;
  c.entry = glm::clamp(origin + t0 * direction, 0.0f, 1.0f);
  c.exit = glm::clamp(origin + t1 * direction, 0.0f, 1.0f);
  // Snap the face coordinate exactly onto the face plane.
  c.entry[kFaceAxis[c.entry_face]] = float(c.entry_face & 1);
  c.exit[kFaceAxis[c.exit_face]] = float(c.exit_face & 1);
  return c;
}

}  // namespace gfield
