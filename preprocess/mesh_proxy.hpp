#pragma once
// The simplified stand-in of a mesh with more faces than a geometry image can use: the geometry
// image is charted, parameterised and cast on the proxy, and its texels are filled from the
// full-resolution surface (surface_projection.hpp), so the image describes the original mesh at
// the cost of a mesh of the proxy's size. Simplification: meshoptimizer's edge collapse
// (meshopt_simplify), borders kept.

#include <cstddef>
#include <string>

#include "geometry/mesh_io.hpp"

namespace gfield {

/// Meshes of more faces than this go through a proxy by default (GeometryImageOptions::
/// proxy_above); the proxy has at most half as many.
inline constexpr size_t kDefaultProxyAbove = 200'000;

struct MeshProxy {
  /// The input with exactly coincident positions welded (same faces, same order: face f is the
  /// input's face f), the surface the image's texels are projected onto.
  TriangleMesh welded;
  /// The simplified mesh (its vertices a subset of welded's).
  TriangleMesh proxy;
  /// meshoptimizer's error bound of the simplification, mesh units (the largest distance the
  /// collapses moved the surface, as it measures it).
  double error = 0.0;
  /// The welded mesh's genus, summed over its components (surface_genus); -1: not a manifold.
  long genus = -1;
  /// Edges of the simplified mesh flipped where it is flat (flat_flips.hpp).
  size_t flat_flips = 0;
  double seconds = 0.0;
};

/// Welds `input` and simplifies it to at most `target_faces` faces (fewer where no collapse is
/// left that keeps the borders). False with an error (no file name) when no face of `input` has
/// a positive area.
bool make_mesh_proxy(const TriangleMesh& input, size_t target_faces, MeshProxy& out,
                     std::string& error);

/// The genus of `mesh` summed over its components, from its Euler characteristic, components
/// and boundary loops (faces with a repeated corner left out); -1 where an edge has more than
/// two faces (no genus to speak of).
long surface_genus(const TriangleMesh& mesh);

/// Exactly coincident positions merged (hash on the bits; -0 and +0 weld): `mesh` with V'
/// positions, its F faces re-indexed in their order.
TriangleMesh weld_positions(const TriangleMesh& mesh);

}  // namespace gfield
