#pragma once
// The geometry-image pipeline (docs/geometry-image.md): repair -> per-component route (orbifold
// for closed genus 0, cut graph + conformal map of a disk otherwise) -> chart packing ->
// rasterisation -> measurements (uv faults, coverage, distortion, reconstruction error).

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/parameterized_mesh.hpp"
#include "gfield/geometry_image.hpp"
#include "preprocess/chart_packing.hpp"
#include "preprocess/mesh_proxy.hpp"
#include "preprocess/repair.hpp"

namespace gfield {

enum class ParameterizationMethod { kAuto, kOrbifold, kSquare };
enum class ComponentSelection { kAll, kLargest };

/// Largest input accepted (faces). Above it the pipeline stops with an error instead of
/// exhausting memory: a build through its proxy peaks at about 0.25 KB per face (the bunny
/// midpoint-subdivided to 4.4M faces: 0.95 GB), one without (a rejected proxy) at about 2 KB.
inline constexpr size_t kMaxFaces = 8'000'000;
/// Image sizes accepted (texels per side).
inline constexpr int kMinImageSize = 8;
inline constexpr int kMaxImageSize = 8192;
/// GeometryImageOptions::size meaning "choose": the smallest of kAutoImageSizes whose mean
/// mesh -> image distance is at most GeometryImageOptions::max_mean_error (else the largest).
inline constexpr int kAutoImageSize = 0;
inline constexpr int kAutoImageSizes[] = {512, 1024};
/// Default GeometryImageOptions::max_mean_error, percent of the input's diagonal.
inline constexpr double kDefaultMaxMeanError = 0.005;
/// Relative padding of the image box (GeometryImage::box = padded_bounds(repaired positions)).
inline constexpr float kBoxPadding = 0.01f;

struct GeometryImageOptions {
  int size = kAutoImageSize;  ///< texels per side, or kAutoImageSize
  /// kAutoImageSize: the mean mesh -> image distance to reach, percent of the input's diagonal.
  double max_mean_error = kDefaultMaxMeanError;
  ParameterizationMethod method = ParameterizationMethod::kAuto;
  ComponentSelection components = ComponentSelection::kAll;
  HoleFilling holes = HoleFilling::kAllButLongest;
  int gutter = 2;  ///< texels between packed charts
  /// Cut regions a chart compresses (protrusions) into charts of their own (chart_split.hpp).
  bool split_protrusions = true;
  int max_split_depth = 2;
  /// Distortion and reconstruction error (the slow part). An automatic size always measures the
  /// mesh -> image distance (it chooses by it, and the ray offset comes from it).
  bool measure = true;
  size_t error_samples = 100000;  ///< area-weighted points per direction
  uint64_t seed = 1;
  /// A mesh of more faces is charted and parameterised as a proxy of at most half as many
  /// (mesh_proxy.hpp), its texels filled from the full surface; 0: never.
  size_t proxy_above = kDefaultProxyAbove;
};

/// Error statistics in percent of the input's bounding-box diagonal.
struct ErrorStats {
  double mean = 0.0;
  double p98 = 0.0;
  double p99 = 0.0;
  double max = 0.0;
  size_t samples = 0;
};

struct ChartReport {
  size_t faces = 0;
  size_t vertices = 0;
  long genus = 0;
  size_t boundary_loops = 0;
  std::string route;    ///< "orbifold", "disk", "cut-graph+disk", "slit+disk", "triangle"
  std::string weights;  ///< "cotangent" / "mean value"
  std::string note;     ///< why a fallback was taken, if one was
  size_t seam_edges = 0;
  size_t flipped = 0;
  size_t degenerate = 0;
  double area = 0.0;  ///< surface area (mesh units squared)
  ChartRect rect;
};

/// A proxy's image is kept where its charts' genus is the mesh's (collapses that pinch or join
/// the surface add handles the charts must cut) and, for an automatic size, its mean mesh ->
/// image distance is at most this many times GeometryImageOptions::max_mean_error; else the
/// image is built from the full mesh.
inline constexpr double kProxyErrorFactor = 2.0;

/// The proxy a large mesh was charted as (GeometryImageOptions::proxy_above); faces = 0: none
/// was tried.
struct ProxyReport {
  bool used = false;  ///< the image kept is the proxy's (else it was rejected)
  size_t input_faces = 0;
  size_t faces = 0;            ///< of the proxy
  double error_percent = 0.0;  ///< meshoptimizer's bound, percent of the input's diagonal
  size_t flat_flips = 0;       ///< edges of the proxy flipped where it is flat (flat_flips.hpp)
  double mean_percent = 0.0;   ///< the proxy image's mean mesh -> image distance (percent)
  long input_genus = -1;       ///< the mesh's genus (-1: not a manifold, not compared)
  long genus = 0;              ///< the proxy's charts' genus, summed
  std::string rejected;        ///< why the proxy's image was not kept; empty when it was
};

struct StageTimes {  ///< seconds
  double proxy = 0.0, repair = 0.0, parameterize = 0.0, pack = 0.0, rasterize = 0.0, measure = 0.0,
         total = 0.0;
};

/// One image size an automatic size tried, and its mean mesh -> image distance (percent of the
/// input's diagonal).
struct SizeTrial {
  int size = 0;
  double mesh_to_image_mean = 0.0;
};

struct GeometryImageReport {
  ProxyReport proxy;
  RepairReport repair;  ///< of the proxy where one is used
  /// The sizes tried, smallest first, the last one kept; empty for a size given.
  std::vector<SizeTrial> size_trials;
  double max_mean_error = 0.0;  ///< the automatic size's target (percent of the diagonal)
  std::string route;  ///< the routes of the charts, e.g. "orbifold" or "orbifold + slit+disk x3"
  std::vector<ChartReport> charts;
  size_t components = 0;          ///< after repair
  size_t dropped_components = 0;  ///< --components largest
  size_t dropped_faces = 0;
  size_t flipped = 0;  ///< over all charts
  size_t degenerate = 0;
  double coverage = 0.0;  ///< fraction of texels inside a chart
  /// sigma1/sigma2 of each face's uv Jacobian, area-weighted mean and 95th percentile.
  double conformal_mean = 0.0, conformal_p95 = 0.0;
  /// (uv area share) / (surface area share) per face, area-weighted percentiles 5, 50, 95.
  double area_p5 = 0.0, area_p50 = 0.0, area_p95 = 0.0;
  ErrorStats mesh_to_image;  ///< input surface -> image surface
  ErrorStats image_to_mesh;  ///< image surface -> input surface
  double diagonal = 0.0;     ///< input bounding-box diagonal (mesh units)
  /// GeometryImage::ray_offset (box diagonals): mesh_to_image's p98, at least kMinRayOffset.
  double ray_offset = kMinRayOffset;
  /// What the albedo was resampled from: "none", or e.g. "1 texture, 2 materials".
  std::string albedo = "none";
  StageTimes seconds;
};

/// Builds the geometry image of `input` (as loaded). `image.source` is left for the caller.
/// `parameterized` receives the repaired mesh (kept components; the proxy's above
/// options.proxy_above faces) with every corner's image uv.
/// With `appearance` (input's, mesh_appearance.hpp) carrying a base colour, image.albedo is the
/// base colour resampled at every texel (docs/geometry-image.md, "Albedo").
/// False with an error in words (no file name) for input it cannot handle.
bool build_geometry_image(const TriangleMesh& input, const GeometryImageOptions& options,
                          GeometryImage& image, ParameterizedMesh& parameterized,
                          GeometryImageReport& report, std::string& error,
                          const MeshAppearance* appearance = nullptr);

/// The surface of a geometry image: texel positions, two triangles per grid quad whose four
/// texels are all covered.
TriangleMesh geometry_image_surface(const GeometryImage& image);

nlohmann::json geometry_image_report_to_json(const GeometryImageReport& report);
/// The inverse of geometry_image_report_to_json. Throws nlohmann::json::exception where `j` is
/// not of that shape.
GeometryImageReport geometry_image_report_from_json(const nlohmann::json& j);
std::string geometry_image_report_to_text(const GeometryImageReport& report);

}  // namespace gfield
