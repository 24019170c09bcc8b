#pragma once
// Objects seen through glass by vertex displacement (Mukai, Makino & Chang 2013, docs/glass.md):
// a vertex behind a parallel glass plate or a hollow glass cylinder is moved to where the eye sees
// it through the glass, so that drawing the moved vertex without the glass gives the refracted
// picture. The math is shaders/lib/glass_displacement.glsl compiled as C++, so the CPU and the
// vertex shader give the same answers. No GL here.
//
// Units: positions in one frame (world for plates, the cylinder's object space for cylinders),
// lengths in scene units, indices of refraction relative to the outside (air = 1).

#include <string>

#include <glm/glm.hpp>

#include "gfield/scene.hpp"

namespace gfield {

/// A parallel glass plate: two parallel planes `thickness` apart around `centre` (infinite, as in
/// the paper's equations), unit `normal` of either sign.
struct GlassPlate {
  glm::vec3 centre{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  float thickness = 0.1f;
  float ior = 1.5f;
};

/// sin(theta) of the paper's equation 5, (y - W) tan(theta) + W tan(phi) = x with Snell's
/// sin(theta) = n sin(phi), solved by Newton's method inside a guaranteed bracket. x >= 0: the
/// vertex's distance from the plate normal through the eye; y > W: its distance along the normal.
float plate_incidence_sine(float x, float y, float thickness, float ior);

/// Where `vertex` is seen from `eye` through `plate` (equations 5, 4 and 2 in the plate's frame,
/// rotated there and back). A vertex inside the plate is seen through the near face alone (the
/// same equations with the glass ending at the vertex); vertices in front come back unchanged.
glm::vec3 plate_displace(const GlassPlate& plate, glm::vec3 eye, glm::vec3 vertex);

/// A hollow glass cylinder in its object space: axis Y through the origin, walls between the
/// inner and the outer radius, infinite along Y in the displacement math.
struct GlassCylinder {
  float outer_radius = 1.0f;
  float inner_radius = 0.9f;
  float ior = 1.5f;
};

/// The interface sequences a ray can take through the hollow cylinder (numbers as GD_PATH_*).
enum class CylinderPath {
  kBothWalls = 0,  ///< outer in, inner in, inner out, outer out: the paper's A, B, C, D
  kVerge = 1,      ///< outer in, total internal reflection at the inner surface, outer out:
                   ///< the band between the inner and the outer silhouette
  kFrontWall = 2,  ///< outer in, inner in: to a point inside the glass
  kBackWall = 3,   ///< inner out, outer out: from the open top through one wall
};

/// Where `vertex` is seen from `eye` through the cylinder along `path` (object space): the path,
/// then the paper's sequence Q -> Q_D -> Q_C -> Q_B -> Q' of one-interface moves (equations 6-8).
/// False (and `seen` = vertex) when no such path reaches the vertex.
bool cylinder_displace(const GlassCylinder& cylinder, CylinderPath path, glm::vec3 eye,
                       glm::vec3 vertex, glm::vec3& seen);

/// The plate of a scene object of shape "slab" (any transform: the faces stay parallel) between
/// its pair of faces `pair`: 0 the Z faces (the plate's thickness), 1 the X faces, 2 the Y faces.
GlassPlate glass_plate(const SceneObject& object, int pair = 0);

/// The cylinder of a scene object of shape "hollow-cylinder" and its object -> world map. False
/// with an error when the transform's scale is not uniform (the walls would not be circular).
bool glass_cylinder(const SceneObject& object, GlassCylinder& cylinder, glm::mat4& to_world,
                    std::string& error);

}  // namespace gfield
