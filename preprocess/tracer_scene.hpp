#pragma once
// The reference tracer's scene (internal to it: reference_tracer.cpp): the scene's objects in
// world space, its meshes as Embree instances and its analytic shapes exact, and the nearest hit
// of a ray among them.

#include <embree3/rtcore.h>

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/environment.hpp"
#include "gfield/scene.hpp"
#include "preprocess/reference_tracer.hpp"

namespace gfield {

inline constexpr unsigned kOpaqueMask = 1u;      // diffuse and mirror objects: block shadow rays
inline constexpr unsigned kDielectricMask = 2u;  // dielectrics: transparent to shadow rays
inline constexpr unsigned kAllMask = kOpaqueMask | kDielectricMask;

struct MeshRecord {
  TriangleMesh mesh;
  MeshAppearance appearance;               ///< its own base colour (materials "texture": "mesh")
  std::vector<glm::dvec3> vertex_normals;  ///< angle-weighted, outward
  double orientation = 1.0;                ///< -1 when the file's winding points inwards
  RTCScene scene = nullptr;
};

struct ObjectRecord {
  SceneObject object;
  glm::dmat4 to_world{1.0};
  glm::dmat4 to_object{1.0};
  glm::dmat3 normal_to_world{1.0};  ///< inverse transpose of the linear part
  glm::dvec3 world_lo{0.0}, world_hi{0.0};
  double diagonal = 0.0;  ///< of the world bounds
  unsigned mask = kOpaqueMask;
};

struct SurfaceHit {
  double t = 0.0;
  int object = -1;
  glm::dvec3 position{0.0};
  glm::dvec3 geometric_normal{0.0};  ///< world, unit, outward
  glm::dvec3 shading_normal{0.0};    ///< world, unit, outward
  glm::dvec2 uv{0.0};
  int face = -1;            ///< mesh hits: the triangle
  glm::dvec3 weights{0.0};  ///< mesh hits: barycentric weights of its corners
  double epsilon = 0.0;     ///< offset for rays leaving this point
};

struct TracerScene {
  Scene scene;
  Environment environment;
  std::vector<MeshRecord> meshes;
  std::vector<ObjectRecord> objects;
  std::vector<int> analytic;            ///< indices of analytic objects
  std::vector<int> instance_to_object;  ///< Embree geometry ID -> object
  RTCDevice device = nullptr;
  RTCScene top = nullptr;
  double extent = 1.0;  ///< scene diagonal, for ray offsets

  TracerScene() = default;
  TracerScene(const TracerScene&) = delete;
  TracerScene& operator=(const TracerScene&) = delete;
  ~TracerScene();

  /// The objects of `input` (its meshes read and built into Embree scenes). False with an error
  /// naming the scene or mesh file.
  bool build(const Scene& input, std::string& error);

  /// Nearest hit in (0, t_max) among objects whose mask meets `mask`.
  bool intersect(const TracerRay& ray, double t_max, unsigned mask, SurfaceHit& hit) const;

  /// A ray leaving `hit` in `direction`, offset to the side of the surface it goes to.
  static TracerRay spawn(const SurfaceHit& hit, glm::dvec3 direction);

 private:
  bool build_mesh(MeshRecord& record, const MeshAsset& asset, std::string& error);
};

}  // namespace gfield
