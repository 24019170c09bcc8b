#include "runtime/methods/intersect_route.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gfield {

double estimated_bvh_nodes(size_t triangles, bool dielectric) {
  const double log_faces = std::log2(std::max<double>(2.0, double(triangles)));
  return dielectric ? 4.24 * log_faces : 3.17 * log_faces - 5.0;
}

Route auto_route(const RouteInputs& mesh) {
  if (!mesh.has_field)
    return {true, "no field"};
  char why[128];
  const double bytes = kBvhBytesPerTriangle * double(mesh.triangles);
  if (bytes > kAutoBvhBudget) {
    std::snprintf(why, sizeof(why), "its BVH would take %.0f MB > %.0f", bytes / 1e6,
                  kAutoBvhBudget / 1e6);
    return {false, why};
  }
  const double nodes = estimated_bvh_nodes(mesh.triangles, mesh.dielectric);
  const double field = mesh.dielectric ? kFieldNodesGlass : kFieldNodesMirror;
  std::snprintf(why, sizeof(why), "~%.0f BVH nodes per %s ray %s %.0f", nodes,
                mesh.dielectric ? "glass" : "mirror", nodes < field ? "<" : ">=", field);
  return {nodes < field, why};
}

}  // namespace gfield
