#pragma once
// The ray families of `gfield verify` (verify.hpp): random segments through a box, view rays
// from around it, and rays leaving a mesh's surface as the runtime casts them.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/geometry_image.hpp"
#include "preprocess/embree_mesh.hpp"

namespace gfield {

/// `count` segments between uniform random points on two different faces of `box` (t in [0,1]).
std::vector<Ray> random_box_rays(const Box& box, size_t count, uint64_t seed);
/// `count` rays from uniform random viewpoints on the sphere of radius one box diagonal around
/// the box centre, each aimed at a uniform random point of the box (unit direction, t >= 0).
std::vector<Ray> random_view_rays(const Box& box, size_t count, uint64_t seed);

/// How far off the surface a ray leaving it starts (mesh units), as the runtime casts it
/// (shaders/lib/scene.glsl, object_epsilon): `path`, the ray itself (GF_MIN_RAY_OFFSET of the
/// box diagonal), and `self`, the lookup of the mesh it leaves (the geometry image's ray offset).
struct SurfaceOffsets {
  float path = 0.0f;
  float self = 0.0f;
};
/// The offsets of rays leaving the surface of `image`'s mesh (box: the field's).
SurfaceOffsets surface_offsets(const GeometryImage& image, const Box& box);

/// Rays that leave the surface of a mesh, with the triangle each leaves (the exact cast ignores
/// it). Unit directions, moved off the surface along the face's normal on the ray's side: the ray
/// by offsets.path (t_min = 2 offsets.path), the parallel ray of its lookup
/// (lookup_first_hit_leaving) from `self_origins` by offsets.self, beyond self_t_min = 2
/// offsets.self; `facing`: +1 where the ray leaves on the side the triangle's winding faces
/// (the geometry image's normals face that way), -1 on the other side; `any_hit`: shadow rays,
/// looked up as such (lookup_first_hit_leaving).
struct SurfaceRays {
  std::vector<Ray> rays;
  std::vector<glm::vec3> self_origins;
  std::vector<float> facing;
  float self_t_min = 0.0f;
  std::vector<int> triangles;
  bool any_hit = false;
};
/// `count` rays from uniform random points of `mesh`'s surface (by area) in uniform random
/// directions over the hemisphere of the face's outward normal.
SurfaceRays random_surface_rays(const TriangleMesh& mesh, size_t count, SurfaceOffsets offsets,
                                uint64_t seed);
/// Up to `count` mirror reflections of random_view_rays(box) at their exact first hits on
/// `embree`'s mesh `mesh`: about the smooth normal (angle-weighted vertex normals), about the
/// face's normal where that would leave below the face (as the runtime reflects).
SurfaceRays mirror_surface_rays(const EmbreeMesh& embree, const TriangleMesh& mesh, const Box& box,
                                size_t count, SurfaceOffsets offsets, uint64_t seed);
/// Up to `count` refractions of random_view_rays(box) into the solid at their exact first hits on
/// `embree`'s mesh `mesh` (about the smooth normal, index of refraction `ior` inside), as the
/// runtime refracts into glass: rays that start inside the solid (facing -1 on a mesh whose
/// normals face out), reflected where the refraction is total.
SurfaceRays glass_surface_rays(const EmbreeMesh& embree, const TriangleMesh& mesh, const Box& box,
                               size_t count, SurfaceOffsets offsets, uint64_t seed,
                               float ior = 1.5f);
/// Up to `count` shadow rays from the exact first hits of random_view_rays(box) on `embree`'s mesh
/// `mesh` towards uniform random light directions, where the light is in front of both the face
/// and the smooth normal, as the runtime casts them (shaders/lib/scene.glsl, light_from): from
/// max(offsets.self, 10 offsets.path) off the face on the viewer's side, looked up from there as
/// shadow rays (any_hit).
SurfaceRays shadow_surface_rays(const EmbreeMesh& embree, const TriangleMesh& mesh, const Box& box,
                                size_t count, SurfaceOffsets offsets, uint64_t seed);
/// The glass path's next step: up to `count` rays leaving the exact hits of
/// glass_surface_rays(... 2 * count ...) on the inside of the surface, refracted out into the open
/// (facing +1) or, where the refraction is total, reflected back into the solid (facing -1).
SurfaceRays glass_inside_rays(const EmbreeMesh& embree, const TriangleMesh& mesh, const Box& box,
                              size_t count, SurfaceOffsets offsets, uint64_t seed,
                              float ior = 1.5f);

}  // namespace gfield
