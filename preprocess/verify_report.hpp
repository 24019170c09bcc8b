#pragma once
// The report of `gfield verify` (and the "accuracy" of an asset report): how a geometry field
// and its image agree with exact casts, per reference mesh, ray family and lookup mode; as a
// struct, as JSON (docs/geometry-field.md, "Verify") and as text.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <nlohmann/json_fwd.hpp>

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
/// The inverse of accuracy_to_json (agree from hit_agreement x rays). Throws
/// nlohmann::json::exception where `j` is not of that shape.
AccuracyStats accuracy_from_json(const nlohmann::json& j);

/// The accuracy against one reference mesh.
struct ReferenceAccuracy {
  std::string mesh;     ///< "built" (NAME.gimage.obj) or "original" (the file built from)
  std::string path;     ///< that mesh's file (printable)
  AccuracyStats table;  ///< the stored table: exact casts between its samples
  /// family ("box_rays", "surface_rays_k1", ...) -> mode ("refined", "refined_last", ...) ->
  /// agreement of that family's lookups in that mode.
  std::map<std::string, std::map<std::string, AccuracyStats>> families;
  /// family of rays leaving the surface -> share of its rays whose exact hit lies within
  /// 2 ray offsets of the start (the lookup tells those from their start by facing only).
  std::map<std::string, double> near_hits;
};

struct VerifyReport {
  std::string name;          ///< the asset, DIR/NAME (printable)
  std::string field;         ///< NAME.gfield.exr (printable)
  int samples_per_side = 0;  ///< N
  int layers = 0;            ///< GeometryField::layers of the field read
  int field_bits = 32;       ///< bits per uv component the lookups read
  int image_size = 0;        ///< n of the geometry image
  float ray_offset = 0.0f;   ///< GeometryImage::ray_offset (box diagonals)
  std::string source;        ///< the image's source mesh name (printable)
  size_t rays_per_family = 0;
  uint64_t seed = 0;
  bool proxy = false;  ///< the image was built through a proxy: rays leave the original's surface
  std::vector<ReferenceAccuracy> references;  ///< the built mesh, then the original where found
  std::string original_note;  ///< why the original is missing ("" when it was found)

  /// The reference the asset describes: the original where the image was built through a
  /// proxy (and the original was found), else the built mesh.
  const ReferenceAccuracy& described() const;
};

nlohmann::json verify_report_to_json(const VerifyReport& report);
/// The inverse of verify_report_to_json. Throws nlohmann::json::exception where `j` is not of
/// that shape.
VerifyReport verify_report_from_json(const nlohmann::json& j);

/// The report as readable text (one table per reference mesh).
std::string verify_report_to_text(const VerifyReport& report);

}  // namespace gfield
