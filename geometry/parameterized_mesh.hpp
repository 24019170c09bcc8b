#pragma once
// The mesh a geometry image was built from (after repair, hole filling and cutting) with the
// geometry-image uv of every triangle corner. The geometry field stores, for each ray, the uv of
// the hit interpolated from these corner uvs, so that the image returns the hit point at that uv.
//
// On disk: NAME.gimage.obj beside NAME.gimage.exr, an OBJ with `v` (mesh coordinates), `vt`
// (geometry-image uv in [0,1]^2) and `f v/vt` triangles, a line "#gfield-counts V T F" (a
// comment to other OBJ readers) before them, and the build id in a comment line
// `# gfield.buildId ID` (gfield/build_id.hpp). Written and read by this module.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"
#include "gfield/box.hpp"
#include "gfield/geometry_image.hpp"

namespace gfield {

struct ParameterizedMesh {
  TriangleMesh mesh;                 ///< V points, F triangles (mesh coordinates)
  std::vector<glm::vec2> corner_uv;  ///< 3F geometry-image uvs, corner c of triangle f at 3f + c
  std::string build_id;              ///< the build's id, the image's (empty: none)
  /// F faces of the input mesh each face is (-1: it fills a hole), as the build knows it; not
  /// saved (empty when read from a file).
  std::vector<int> source_face;
};

/// The uv file that belongs to an image file: "X.gimage.exr" -> "X.gimage.obj".
std::string parameterized_mesh_path(const std::string& geometry_image_path);

bool save_parameterized_mesh(const std::string& filename, const ParameterizedMesh& pm,
                             std::string& error);
/// False with a one-line "FILE[:LINE]: problem" for a missing, empty or malformed file, one
/// whose last line has no end or whose v, vt, f lines disagree with its counts line (truncated;
/// files without a counts line, of older builds, are read without that check), coordinates
/// that are not finite or beyond kMaxAssetCoordinate, uvs outside [-1, 2]^2 (a corner of a triangle
/// crossing an orbifold chart's border may lie outside [0,1]^2), indices out of range (read
/// as 64-bit values), faces that are not triangles, or no faces.
bool load_parameterized_mesh(const std::string& filename, ParameterizedMesh& pm,
                             std::string& error);

/// The build id of a parameterised mesh file, read from its leading comment lines only (empty:
/// none). False with an error when the file cannot be read.
bool read_parameterized_mesh_build_id(const std::string& filename, std::string& build_id,
                                      std::string& error);

/// Loads the parameterised mesh of `image` (read from `image_file`): the file beside it
/// (parameterized_mesh_path), refused when its build id differs from the image's (an error naming
/// both files).
bool load_parameterized_mesh_of(const GeometryImage& image, const std::string& image_file,
                                ParameterizedMesh& pm, std::string& error);

/// True when every vertex of `pm` (as a float) lies in `box`: a parameterised mesh and a
/// geometry image (or field) of one build always do.
bool mesh_inside_box(const ParameterizedMesh& pm, const Box& box);

}  // namespace gfield
