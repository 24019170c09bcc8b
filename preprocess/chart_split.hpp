#pragma once
// Cutting protrusions into charts of their own. A conformal map shrinks protrusions (ears, legs,
// fingers, spouts) exponentially with their length, leaving them a few texels; the faces a chart
// compresses below a threshold of its mean texel density are grouped into connected regions,
// which are then charted separately (and the rest, now with holes, too).

#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"

namespace gfield {

struct SplitOptions {
  double threshold = 0.1;  ///< uv area share / surface area share below which a face is compressed
  double min_area_fraction = 0.002;  ///< smaller compressed regions stay in the chart
  int grow_rings = 2;  ///< the regions grow by this many rings of faces (clean borders)
};

/// Groups of faces of `mesh` (a connected component with chart uvs `corner_uv`, 3 per face) to
/// chart separately: the rest first, then each compressed region (with any part of the rest it
/// encloses). Empty when nothing is compressed enough to split.
std::vector<std::vector<int>> split_compressed_regions(const TriangleMesh& mesh,
                                                       const std::vector<glm::dvec2>& corner_uv,
                                                       const SplitOptions& options);

}  // namespace gfield
