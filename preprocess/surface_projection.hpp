#pragma once
// Texels of a geometry image rasterised from a proxy (mesh_proxy.hpp) moved onto the
// full-resolution surface: each covered texel's point goes along its normal to the original
// mesh (or to its closest point where that line misses it nearby), and takes the original's
// interpolated normal (turned to agree with the proxy's) and its base colour there.

#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/geometry_image.hpp"
#include "preprocess/closest_point.hpp"
#include "preprocess/embree_mesh.hpp"

namespace gfield {

class SurfaceProjection {
 public:
  /// `input` as read and its `appearance` (null: no base colour); `welded`, its positions welded
  /// (MeshProxy::welded: same faces in the same order); `reach`: how far (mesh units) a texel
  /// looks along its normal for the surface. The references must outlive this object. False with
  /// an error when Embree cannot build the BVH.
  bool build(const TriangleMesh& input, const MeshAppearance* appearance,
             const TriangleMesh& welded, double reach, std::string& error);

  /// Moves every covered texel of `image` (position, normal, albedo where the appearance has a
  /// base colour) onto the surface: to the nearest crossing of the line through the texel along
  /// its (proxy) normal within the reach, else to the closest point if it lies within the reach;
  /// texels farther from the surface (faces that fill holes) keep the proxy's point and normal
  /// and take the colour of the closest point. `image.albedo` is sized n*n when it has one.
  void project(GeometryImage& image) const;

  /// The full surface (welded).
  const TriangleMesh& surface() const { return *welded_; }

  /// Whether the image takes a base colour from the original.
  bool has_albedo() const { return appearance_ != nullptr; }

 private:
  /// The input's base colour at a point of the welded surface.
  glm::vec3 base_color(const ClosestPoint& c) const;

  const TriangleMesh* input_ = nullptr;
  const MeshAppearance* appearance_ = nullptr;
  const TriangleMesh* welded_ = nullptr;
  double reach_ = 0.0;
  std::vector<glm::dvec3> normals_;  ///< V angle-weighted unit normals of `welded`
  EmbreeMesh embree_;
};

}  // namespace gfield
