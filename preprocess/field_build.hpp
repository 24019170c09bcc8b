#pragma once
// Geometry field precomputation (Li et al. 2006, section 2) with Embree 3.
//
// For every pair (entry sample, exit sample) of the 6 N^2 box samples on different faces, the ray
// from the entry point towards the exit point (mesh coordinates, t in [0, 1]) is cast against the
// mesh the geometry image was built from. Its first K hits are stored in order, one layer each,
// as the geometry-image uv of the hit point, interpolated from the hit triangle's corner uvs with
// Embree's barycentrics; a layer past the line's last hit stores kFieldMiss, a pair on one face
// kFieldNoRay. The casts (field_casts.hpp), in coherent packets of 8 rays (rtcIntersect8, TBB):
// K = 1, a first-hit cast of every ray; K > 1, one traversal per line (the rays entry -> exit
// and exit -> entry are one line) that collects its hits with an intersection filter, K + 1 of
// them nearest the entry, and a traversal from the exit only for a line with more than K.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/parameterized_mesh.hpp"
#include "gfield/geometry_field.hpp"
#include "gfield/geometry_image.hpp"
#include "preprocess/embree_mesh.hpp"
#include "preprocess/job_control.hpp"

namespace gfield {

/// Accepted samples per side N (the table has (6N^2)^2 entries: 0.3 MB at N = 4, 1.5 GB at 48).
inline constexpr int kMinSamplesPerSide = 4;
inline constexpr int kMaxSamplesPerSide = 48;

/// `layers` argument of the build: choose K, the smallest that stores every hit of at least
/// kLayerCoverage of the lines (kMaxFieldLayers when none does).
inline constexpr int kAutoLayers = 0;
inline constexpr double kLayerCoverage = 0.999;

/// Peak bytes of building and writing a field with N samples per side and `layers` layers
/// (kAutoLayers: kMaxFieldLayers are built): the float uv table (8 bytes per entry and layer)
/// plus the EXR writer's copy (4 bytes per entry and layer for HALF, 8 for FLOAT).
size_t field_memory_estimate(int samples_per_side, int layers, bool half_precision);

/// Available physical memory in bytes (Linux MemAvailable), 0 when unknown.
size_t available_memory();

/// Checks N against [kMinSamplesPerSide, kMaxSamplesPerSide], `layers` against
/// [kAutoLayers, kMaxFieldLayers] and the memory estimate against the available memory. False
/// with an error that states the figures.
bool check_field_size(int samples_per_side, int layers, bool half_precision, std::string& error);

struct FieldBuildStats {
  size_t rays = 0;  ///< rays cast (pairs on different faces)
  size_t hits = 0;  ///< of those, rays that hit the mesh
  int layers = 1;   ///< K stored
  /// Hits looked for per line: K, or kMaxFieldLayers + 1 when K was chosen (kAutoLayers).
  int collected = 1;
  /// lines_by_hits[h]: rays with exactly h hits for h < collected; [collected]: rays with at
  /// least `collected` hits (not counted further).
  std::array<size_t, kMaxFieldLayers + 2> lines_by_hits{};
  double seconds = 0.0;
};

/// Share of the rays whose every hit fits into `layers` layers; negative when the build did not
/// look far enough along the lines to know (collected <= layers).
double layer_coverage(const FieldBuildStats& stats, int layers);

/// Builds the field of `pm` (the parameterised mesh of `image`, already in `embree`) in the
/// image's box with N samples per side and `layers` layers K (1..kMaxFieldLayers, or kAutoLayers).
/// A hit whose uv falls where the image's bilinear patch reaches into uncovered (padding) texels
/// is moved to the nearby covered patch point closest to the hit (snap_to_covered).
/// `field.source` is left to the caller. False with an error for N or K out of range or a mesh
/// whose corner uvs do not match its triangles, and with kInterrupted when `control` asked to
/// stop (it hears the casts' progress, stage "field").
bool build_geometry_field(const ParameterizedMesh& pm, const EmbreeMesh& embree,
                          const GeometryImage& image, int samples_per_side, int layers,
                          GeometryField& field, std::string& error,
                          FieldBuildStats* stats = nullptr, const JobControl* control = nullptr);

/// Which bilinear patches of `image` have all 4 texels covered: (n-1)^2 flags, patch (i, j)
/// (texels i..i+1, j..j+1) at j * (n-1) + i.
std::vector<uint8_t> covered_patches(const GeometryImage& image);

/// `uv` itself when the 2 x 2 texels of its bilinear patch are all covered; otherwise, of `uv`
/// and the points of the fully covered patches within 2 texels, the one whose image position is
/// closest to `hit` (padding texels are copies of other texels, so a lookup there can land far
/// from the surface). `patches` = covered_patches(image).
glm::vec2 snap_to_covered(const GeometryImage& image, const std::vector<uint8_t>& patches,
                          glm::vec2 uv, glm::vec3 hit);

/// Casts exactly the rays and packets of build_geometry_field and stores nothing (the references
/// of the build benchmark): `layers` = 1, the bare first-hit cast of every ray; K > 1, the
/// traversals of every line of the build of K layers (K = kMaxFieldLayers + 1: of the chosen K).
/// Returns the number of rays that hit.
size_t cast_field_rays(const EmbreeMesh& embree, const Box& box, int samples_per_side,
                       int layers = 1);

}  // namespace gfield
