#pragma once
// The measurements of a geometry image against the mesh it describes (docs/geometry-image.md,
// "Report"): the distances between the two surfaces in both directions (area-weighted random
// points, exact closest points), the ray offset taken from them, and the map's distortion.

#include "geometry/mesh_io.hpp"
#include "geometry/parameterized_mesh.hpp"
#include "gfield/geometry_image.hpp"
#include "preprocess/geometry_image_build.hpp"

namespace gfield {

/// Bounding-box diagonal of `mesh` (mesh units).
double bounds_diagonal(const TriangleMesh& mesh);

/// With options.measure or an automatic size (which chooses by it): the mesh -> image distance
/// and the ray offset into `report` (report.diagonal set).
void measure_mesh_to_image(const TriangleMesh& input, const GeometryImage& image,
                           const GeometryImageOptions& options, GeometryImageReport& report);

/// The distortion and the image -> mesh distance of the image kept into `report`.
void measure_image_to_mesh(const TriangleMesh& input, const GeometryImage& image,
                           const ParameterizedMesh& parameterized,
                           const GeometryImageOptions& options, GeometryImageReport& report);

}  // namespace gfield
