#pragma once
// Accuracy of a geometry field + geometry image against exact Embree ray casts (the ground
// truth): the stored table itself, and the lookup modes on arbitrary rays.

#include <cstdint>
#include <string>
#include <vector>

#include "gfield/confined_path.hpp"
#include "gfield/field_lookup.hpp"
#include "preprocess/asset_files.hpp"
#include "preprocess/embree_mesh.hpp"
#include "preprocess/verify_rays.hpp"
#include "preprocess/verify_report.hpp"

namespace gfield {

/// The table itself (`embree` holds `mesh`): `pairs` random sample pairs on different faces; the
/// exact cast from entry to exit sample vs the stored uv (its position read from the geometry
/// image).
AccuracyStats verify_table(const GeometryField& field, const GeometryImage& image,
                           const EmbreeMesh& embree, const TriangleMesh& mesh, size_t pairs,
                           uint64_t seed);

/// Each ray's lookup (first hit, or last hit with `last`) vs the exact cast. `embree` holds
/// `mesh`. `ignored`: empty, or the triangle each ray leaves (SurfaceRays::triangles), which
/// the exact cast from its origin ignores.
AccuracyStats verify_lookup(const FieldLookup& lookup, const EmbreeMesh& embree,
                            const TriangleMesh& mesh, const std::vector<Ray>& rays, LookupMode mode,
                            bool last = false, const std::vector<int>& ignored = {});
/// Rays leaving the surface: each looked up as lookup_first_hit_leaving vs the exact cast from
/// its origin that ignores the triangle it leaves.
AccuracyStats verify_lookup(const FieldLookup& lookup, const EmbreeMesh& embree,
                            const TriangleMesh& mesh, const SurfaceRays& rays, LookupMode mode);

struct VerifyOptions {
  size_t rays = 1000000;  ///< arbitrary rays per family; the table subset uses as many pairs
  uint64_t seed = 1;
  /// Bits per uv component the lookups read the field at, as the GPU stores it (8, 16; 32:
  /// as loaded; gfield/gpu_storage.hpp quantized_field).
  int field_bits = 32;
  std::string original;       ///< original mesh file; empty: from NAME.report.json or the source
  std::string original_part;  ///< glTF: its mesh (MeshSource::part); from the report with it
  /// Whether the original mesh may read files outside its folder (--allow-outside-paths).
  OutsidePaths original_outside_paths = OutsidePaths::kRefused;
  /// The image was built through a proxy (mesh_proxy.hpp): rays leaving the surface leave the
  /// original's (also when NAME.report.json says so).
  bool proxy = false;
};

/// Verifies the asset NAME (NAME.gfield.exr, NAME.gimage.exr, NAME.gimage.obj) against the mesh
/// it was built from and, where found, against the original file: the table, box rays and view
/// rays with all K layers; against the built mesh also rays leaving its surface (surface_rays,
/// mirror_rays, glass_rays), with the first layer (K = 1) and with all K (against the original
/// instead where the image was built through a proxy, VerifyOptions::proxy). The report: see
/// docs/geometry-field.md. False with an error "FILE: problem", also when the files (and
/// NAME.report.json, where present) are of different builds (gfield/build_id.hpp).
bool verify_asset(const std::string& name, const VerifyOptions& options, VerifyReport& report,
                  std::string& error);
/// The same for the files `read` (a build's staged files), reported as asset NAME's.
bool verify_asset_files(const AssetFiles& read, const std::string& name,
                        const VerifyOptions& options, VerifyReport& report, std::string& error);

}  // namespace gfield
