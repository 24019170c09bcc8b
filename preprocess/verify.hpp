#pragma once
// Accuracy of a geometry field + geometry image against exact Embree ray casts (the ground
// truth): the stored table itself, and the lookup modes on arbitrary rays.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "gfield/confined_path.hpp"
#include "gfield/field_lookup.hpp"
#include "preprocess/asset_files.hpp"
#include "preprocess/embree_mesh.hpp"
#include "preprocess/verify_rays.hpp"

namespace gfield {

/// Agreement of some answers with exact casts. Position errors are in % of the box diagonal and
/// normal errors in degrees, over the rays that both the answer and the exact cast call a hit.
/// The exact normal is the mesh's smooth normal (area-weighted vertex normals interpolated with
/// the hit's barycentrics), the field the geometry image samples.
struct AccuracyStats {
  size_t rays = 0;
  size_t agree = 0;        ///< same hit/miss verdict
  size_t exact_hits = 0;   ///< hits of the exact cast
  size_t answer_hits = 0;  ///< hits of the answer under test
  size_t both_hit = 0;
  double position_median = 0.0;
  double position_p95 = 0.0;
  double position_p99 = 0.0;
  double normal_median = 0.0;  ///< angle between the answer's normal and the exact face normal
  double normal_p95 = 0.0;
  double seconds = 0.0;  ///< time of the answers under test (lookups), not of the exact casts

  double hit_agreement() const { return rays == 0 ? 0.0 : double(agree) / double(rays); }
};

/// The 95% confidence interval of a share of `agree` in `rays` (Wilson score interval): where
/// the hit/miss agreement of every ray of the family lies, given the rays sampled.
glm::dvec2 agreement_interval(size_t agree, size_t rays);

nlohmann::json accuracy_to_json(const AccuracyStats& stats);

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
/// mirror_rays), with the first layer (K = 1) and with all K (against the original instead
/// where the image was built through a proxy, VerifyOptions::proxy). The report: see
/// docs/geometry-field.md. False with an error "FILE: problem", also when the files (and
/// NAME.report.json, where present) are of different builds (gfield/build_id.hpp).
bool verify_asset(const std::string& name, const VerifyOptions& options, nlohmann::json& report,
                  std::string& error);
/// The same for the files `read` (a build's staged files), reported as asset NAME's.
bool verify_asset_files(const AssetFiles& read, const std::string& name,
                        const VerifyOptions& options, nlohmann::json& report, std::string& error);

/// The reference of a verify report that the asset describes: the original where the image was
/// built through a proxy (and the original was found), else the built mesh.
const nlohmann::json& described_reference(const nlohmann::json& report);

/// The report as readable text (one table per reference mesh).
std::string verify_report_to_text(const nlohmann::json& report);

}  // namespace gfield
