#pragma once
// A geometry image drawn as a mesh: its grid of texel centres, triangulated where covered (the
// fallback surface of a parameterised mesh that is missing).

#include <vector>

#include "gfield/geometry_image.hpp"

namespace gfield {

/// Grid triangles of a geometry image: two per quad of texel centres whose 4 corners are covered
/// (A > 0.5), as indices j * n + i. Quads are split along the shorter diagonal.
std::vector<unsigned> geometry_image_triangles(const GeometryImage& image);

}  // namespace gfield
