#pragma once
// d_n per geometry-image texel (Wyman 2005): the distance from the texel's surface point along
// its negative normal to the first other surface of the mesh, cast exactly with Embree against
// the mesh the image was resampled from (NAME.gimage.obj). Written as NAME.thickness.exr
// (gfield/thickness.hpp) by `gfield thickness`.

#include <string>

#include "geometry/mesh_io.hpp"
#include "gfield/geometry_image.hpp"
#include "gfield/thickness.hpp"

namespace gfield {

struct ThicknessStats {
  size_t covered_texels = 0;  ///< texels with A > 0.5 (the ones cast)
  size_t misses = 0;          ///< covered texels whose inward ray found no surface (stored 0)
  double seconds = 0.0;       ///< BVH build + casts
};

/// Casts one ray per covered texel of `image` from P along -N (starting 1e-5 of the box diagonal
/// away from P) against `mesh` (same coordinates as the image). Padding texels get 0.
bool compute_thickness(const GeometryImage& image, const TriangleMesh& mesh, ThicknessMap& map,
                       ThicknessStats& stats, std::string& error);

/// Reads NAME.gimage.exr and NAME.gimage.obj, writes NAME.thickness.exr (atomically).
bool write_thickness_file(const std::string& name, ThicknessStats& stats, std::string& error);

}  // namespace gfield
