#pragma once
// Thickness maps: for every texel of a geometry image, d_n, the distance from the surface point
// along the negative normal to the other side of the object (Wyman 2005, "An approximate
// image-space approach for interactive refraction": the per-vertex distance that the runtime's
// `wyman2005` method interpolates with the back-face distance d_v).
//
// File NAME.thickness.exr (docs/image-space-refraction.md): n x n like NAME.gimage.exr, one FLOAT
// channel `D` (mesh units; 0 in padding texels and where the inward ray found no surface),
// header attributes gfield.format = "thickness", gfield.version = 1, gfield.boxMin/boxMax and
// gfield.source copied from the geometry image.

#include <string>
#include <vector>

#include "gfield/box.hpp"

namespace gfield {

struct ThicknessMap {
  int size = 0;                 ///< n, texels per side (the geometry image's)
  Box box;                      ///< the geometry image's box
  std::string source;           ///< mesh file name (the geometry image's)
  std::vector<float> distance;  ///< n*n d_n in mesh units, index j * n + i (as the image)
};

/// "DIR/X.gimage.exr" -> "DIR/X.thickness.exr" (any other name: the name + ".thickness.exr").
std::string thickness_path(const std::string& geometry_image_path);

bool save_thickness_map(const std::string& filename, const ThicknessMap& map, std::string& error);
/// False with "FILE: problem" (not a thickness map, wrong version, missing channel, larger than
/// kMaxGeometryImageSide, a box beyond +-1e16, a distance not in [0, 1e17], a header claiming more
/// than the file holds).
bool load_thickness_map(const std::string& filename, ThicknessMap& map, std::string& error);

}  // namespace gfield
