#include "preprocess/thickness.hpp"

#include <atomic>

#include <tbb/parallel_for.h>

#include "geometry/parameterized_mesh.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/embree_mesh.hpp"

namespace gfield {

bool compute_thickness(const GeometryImage& image, const TriangleMesh& mesh, ThicknessMap& map,
                       ThicknessStats& stats, std::string& error) {
  Stopwatch watch;
  EmbreeMesh embree;
  if (!embree.build(mesh, error))
    return false;
  const int n = image.size;
  map = {};
  map.size = n;
  map.box = image.box;
  map.source = image.source;
  map.distance.assign(size_t(n) * size_t(n), 0.0f);
  const float offset = 1e-5f * diagonal(image.box);
  std::atomic<size_t> covered{0}, misses{0};
  tbb::parallel_for(0, n, [&](int j) {
    size_t row_covered = 0, row_misses = 0;
    for (int i = 0; i < n; ++i) {
      const size_t t = texel_index(image, i, j);
      if (image.coverage[t] <= 0.5f)
        continue;
      ++row_covered;
      const RayHit hit = intersect(embree, image.position[t], -image.normal[t], offset);
      if (hit.hit)
        map.distance[t] = hit.t;
      else
        ++row_misses;
    }
    covered += row_covered;
    misses += row_misses;
  });
  stats.covered_texels = covered;
  stats.misses = misses;
  stats.seconds = watch.seconds();
  return true;
}

bool write_thickness_file(const std::string& name, ThicknessStats& stats, std::string& error) {
  const std::string image_path = name + ".gimage.exr";
  GeometryImage image;
  if (!load_geometry_image(image_path, image, error))
    return false;
  ParameterizedMesh pm;
  const std::string mesh_path = parameterized_mesh_path(image_path);
  if (!load_parameterized_mesh_of(image, image_path, pm, error))
    return false;
  if (!mesh_inside_box(pm, image.box)) {
    error = mesh_path + ": the mesh does not lie inside the geometry image's box (" + image_path +
            "): they do not belong together";
    return false;
  }
  ThicknessMap map;
  if (!compute_thickness(image, pm.mesh, map, stats, error))
    return false;
  return save_thickness_map(thickness_path(image_path), map, error);
}

}  // namespace gfield
