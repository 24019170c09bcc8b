#pragma once
// The CPU geometry of the glass method (runtime/methods/glass.*, Mukai et al. 2013): the
// triangles of the opaque analytic shapes and of the glass, the glass's refraction classes (the
// sequences of glass surfaces an eye line crosses) and the plate of each of a slab's face pairs.

#include <vector>

#include <glm/glm.hpp>

#include "gfield/glass_displacement.hpp"
#include "gfield/gpu_contract.hpp"
#include "gfield/scene.hpp"
#include "runtime/gpu_assets.hpp"

namespace gfield {

/// Refraction classes: 0 none; slab: 1 + the face pair (Z, X, Y) the line enters; hollow
/// cylinder: 4 + GD_PATH_* (both walls, verge, front wall, back wall). The contract's
/// GLASS_CLASSES.
inline constexpr int kGlassClasses = gpu::GLASS_CLASSES;

/// Triangles in object space.
struct TriangleSoup {
  std::vector<GpuVertex> vertices;
  std::vector<unsigned> indices;
};

/// Triangles of an analytic opaque shape in object space, edges at most `max_edge` long (uv as
/// geometry/analytic_primitives.cpp). False for meshes and hollow cylinders.
bool tessellate(const Shape& shape, float max_edge, TriangleSoup& soup);

/// Glass triangles for peeling (world space, 4 floats each: position and surface number),
/// wound counter-clockwise seen from outside the solid.
struct GlassSoup {
  std::vector<float> data;
  void triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 outward, float surface);
};
/// The peeling triangles of a slab (surfaces 0, 1, 2: its Z, X, Y face pairs) or a hollow
/// cylinder (0 outer wall, 1 inner wall, 2 rims).
GlassSoup glass_triangles(const SceneObject& object);

/// The class of a sequence of peeled surface codes (shaders/glass_composite.frag's glass_class),
/// -1 for a pattern the displacement does not model (traced per pixel there).
int glass_class(ShapeType shape, const std::vector<int>& codes, bool trace_verge);

/// The classes a frame of `camera` (aspect width / height) needs: those of the straight eye
/// lines of a grid of 128 rows of pixels against the exact glass, class 0 always, ascending.
std::vector<int> classes_present(const SceneObject& glass, const Camera& camera, float aspect,
                                 bool trace_verge);

}  // namespace gfield
