#pragma once
// --intersect auto: whether a mesh is met by a lookup in its geometry field or traced exactly
// through its BVH, from a cost model calibrated on bench_runtime_complexity (docs/runtime.md,
// "--intersect auto").

#include <cstddef>
#include <string>

namespace gfield {

/// What the model knows of one mesh.
struct RouteInputs {
  size_t triangles = 0;     ///< of its rasterised mesh
  bool has_field = false;   ///< its geometry image and field are loaded
  bool dielectric = false;  ///< some object of the scene makes it glass
};

struct Route {
  bool bvh = true;  ///< traced through its BVH (else looked up in its field)
  std::string why;  ///< one phrase, for the panel and --bench: "~35 BVH nodes per ray < 58"
};

/// The BVH nodes a ray visits in a mesh of `triangles`, estimated: a + b log2(triangles), the
/// line through bench_runtime_complexity's counts from 5.9K to 1.1M faces (mirror: 35 to 59
/// nodes, glass rays, which cross the solid: 53 to 85).
double estimated_bvh_nodes(size_t triangles, bool dielectric);

/// The field's cost in BVH node visits, where the measured tracing times would meet on
/// llvmpipe: the mean over bench_runtime_complexity's four meshes and two runs of (field tracing
/// time / BVH tracing time) x BVH nodes per ray: for mirrors 33 to 70 per mesh and run, 53 on
/// the mean; for glass 37 to 59, 49. The ratios depend on the CPU llvmpipe runs on
/// (docs/runtime.md). The bytes of a BVH larger than kAutoBvhBudget send a mesh to its field
/// whatever the time.
inline constexpr double kFieldNodesMirror = 53.0;
inline constexpr double kFieldNodesGlass = 49.0;
/// BVH bytes per triangle (nodes, triangles, shading: 373 MB for 1.1M faces) and the budget.
inline constexpr double kBvhBytesPerTriangle = 340.0;
inline constexpr double kAutoBvhBudget = 1024.0 * 1024.0 * 1024.0;

/// The route --intersect auto takes for a mesh: its BVH without a field; its field where its
/// BVH would exceed kAutoBvhBudget or a ray would visit more nodes than the field costs.
Route auto_route(const RouteInputs& mesh);

}  // namespace gfield
