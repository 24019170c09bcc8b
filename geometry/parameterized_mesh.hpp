#pragma once
// The mesh a geometry image was built from (after repair, hole filling and cutting) with the
// geometry-image uv of every triangle corner. The geometry field stores, for each ray, the uv of
// the hit interpolated from these corner uvs, so that the image returns the hit point at that uv.
//
// On disk: NAME.gimage.obj beside NAME.gimage.exr, an OBJ with `v` (mesh coordinates), `vt`
// (geometry-image uv in [0,1]^2) and `f v/vt` triangles. Written and read by this module.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"

namespace gfield {

struct ParameterizedMesh {
  TriangleMesh mesh;                 ///< V points, F triangles (mesh coordinates)
  std::vector<glm::vec2> corner_uv;  ///< 3F geometry-image uvs, corner c of triangle f at 3f + c
};

/// The uv file that belongs to an image file: "X.gimage.exr" -> "X.gimage.obj".
std::string parameterized_mesh_path(const std::string& geometry_image_path);

bool save_parameterized_mesh(const std::string& filename, const ParameterizedMesh& pm,
                             std::string& error);
bool load_parameterized_mesh(const std::string& filename, ParameterizedMesh& pm,
                             std::string& error);

}  // namespace gfield
