#pragma once
// The object's box and the sampling of its faces (DESIGN.md, "Formats").
//
// Every object is normalised into the unit cube [0,1]^3 of its box. Each of the 6 cube faces
// carries N x N samples at their centres; a ray through the box is given by its entry and exit
// points on the faces, and the geometry field is indexed by the pair (entry sample, exit sample).
//
// Sample index k = face * N^2 + b * N + a, faces ordered -X, +X, -Y, +Y, -Z, +Z. On X faces
// (a, b) index (y, z), on Y faces (x, z), on Z faces (x, y). Sample (a, b) sits at face
// coordinates ((a + 0.5) / N, (b + 0.5) / N).

#include <glm/glm.hpp>

namespace gfield {

/// Axis-aligned box in mesh coordinates; `min` maps to (0,0,0) of the unit cube, `max` to (1,1,1).
struct Box {
  glm::vec3 min{0.0f};
  glm::vec3 max{1.0f};
};

/// Cube faces in the order of the sample index.
enum CubeFace : int { kNegX = 0, kPosX = 1, kNegY = 2, kPosY = 3, kNegZ = 4, kPosZ = 5 };

/// One sample on a cube face: face in [0,6), a and b in [0,N).
struct FaceSample {
  int face = 0;
  int a = 0;
  int b = 0;
};

/// A line crossing the unit cube. `t_entry`/`t_exit` are parameters along the ray that was clipped
/// (any sign: a ray starting inside the cube has t_entry < 0); `entry`/`exit` are unit-cube points.
struct CubeCrossing {
  bool hit = false;
  float t_entry = 0.0f;
  float t_exit = 0.0f;
  glm::vec3 entry{0.0f};
  glm::vec3 exit{0.0f};
  int entry_face = -1;
  int exit_face = -1;
};

/// Mesh coordinates -> unit-cube coordinates (per axis; a flat axis maps to 0.5).
glm::vec3 to_unit_cube(const Box& box, glm::vec3 p);
/// Unit-cube coordinates -> mesh coordinates.
glm::vec3 from_unit_cube(const Box& box, glm::vec3 u);
/// Mesh direction -> unit-cube direction (scales per axis, not normalised).
glm::vec3 direction_to_unit_cube(const Box& box, glm::vec3 d);
/// Length of the box diagonal in mesh units.
float diagonal(const Box& box);
/// Bounds of `points` grown by `relative_padding` of the diagonal on every side (a degenerate
/// extent gets the same absolute padding so every axis has a positive size).
Box padded_bounds(const glm::vec3* points, size_t count, float relative_padding);

/// 6 N^2: the number of samples on the cube (N samples per side of each face).
inline int sample_count(int n) {
  return 6 * n * n;
}
/// (face, a, b) -> sample index k.
inline int sample_index(FaceSample s, int n) {
  return s.face * n * n + s.b * n + s.a;
}
/// Sample index k -> (face, a, b).
inline FaceSample face_sample(int k, int n) {
  const int face = k / (n * n);
  const int r = k - face * n * n;
  return {face, r % n, r / n};
}

/// Face coordinates (s, t) in [0,1]^2 on `face` -> point on the unit cube.
glm::vec3 face_point(int face, glm::vec2 st);
/// Point on (or near) `face` of the unit cube -> its face coordinates (s, t), not clamped.
glm::vec2 face_coords(int face, glm::vec3 p);
/// The centre of sample `s` on the unit cube.
glm::vec3 sample_point(FaceSample s, int n);
/// Face coordinates -> continuous sample coordinates: sample centres sit at integers, so (a, b) of
/// the nearest sample is round(), and the 2 x 2 surrounding samples are floor() and floor() + 1.
inline glm::vec2 sample_coords(glm::vec2 st, int n) {
  return st * float(n) - 0.5f;
}
/// The nearest sample on `face` to face coordinates `st` (clamped to the face).
FaceSample nearest_sample(int face, glm::vec2 st, int n);

/// Clips the line origin + t * direction (unit-cube coordinates) against the unit cube (slab
/// test, all t). Entry and exit faces are the slabs that define t_entry and t_exit. A zero or
/// non-finite direction gives hit = false.
CubeCrossing clip_to_unit_cube(glm::vec3 origin, glm::vec3 direction);

}  // namespace gfield
