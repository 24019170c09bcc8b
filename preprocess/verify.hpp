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

/// `count` segments between uniform random points on two different faces of `box` (t in [0,1]).
std::vector<Ray> random_box_rays(const Box& box, size_t count, uint64_t seed);
/// `count` rays from uniform random viewpoints on the sphere of radius one box diagonal around
/// the box centre, each aimed at a uniform random point of the box (unit direction, t >= 0).
std::vector<Ray> random_view_rays(const Box& box, size_t count, uint64_t seed);

/// How far off the surface a ray leaving it starts (mesh units), as the runtime casts it
/// (shaders/lib/scene.glsl, object_epsilon): `path`, the ray itself (GF_MIN_RAY_OFFSET of the
/// box diagonal), and `self`, the lookup of the mesh it leaves (the geometry image's ray offset).
struct SurfaceOffsets {
  float path = 0.0f;
  float self = 0.0f;
};
/// The offsets of rays leaving the surface of `image`'s mesh (box: the field's).
SurfaceOffsets surface_offsets(const GeometryImage& image, const Box& box);

/// Rays that leave the surface of a mesh, with the triangle each leaves (the exact cast ignores
/// it). Unit directions, moved off the surface along the face's normal on the ray's side: the ray
/// by offsets.path (t_min = 2 offsets.path), the parallel ray of its lookup
/// (lookup_first_hit_leaving) from `self_origins` by offsets.self, beyond self_t_min = 2
/// offsets.self; `facing`: +1 where the ray leaves on the side the triangle's winding faces
/// (the geometry image's normals face that way), -1 on the other side.
struct SurfaceRays {
  std::vector<Ray> rays;
  std::vector<glm::vec3> self_origins;
  std::vector<float> facing;
  float self_t_min = 0.0f;
  std::vector<int> triangles;
};
/// `count` rays from uniform random points of `mesh`'s surface (by area) in uniform random
/// directions over the hemisphere of the face's outward normal.
SurfaceRays random_surface_rays(const TriangleMesh& mesh, size_t count, SurfaceOffsets offsets,
                                uint64_t seed);
/// Up to `count` mirror reflections of random_view_rays(box) at their exact first hits on
/// `embree`'s mesh `mesh`: about the smooth normal (angle-weighted vertex normals), about the
/// face's normal where that would leave below the face (as the runtime reflects).
SurfaceRays mirror_surface_rays(const EmbreeMesh& embree, const TriangleMesh& mesh, const Box& box,
                                size_t count, SurfaceOffsets offsets, uint64_t seed);

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
