#pragma once
// Geometry field precomputation (Li et al. 2006, section 2) with Embree 3.
//
// For every line through two of the 6 N^2 box samples on different faces (mesh coordinates, t in
// [0, 1] from the lower sample), its hits are cast against the mesh the geometry image was built
// from and stored in the compact field (gfield/field_lines.hpp): each as the geometry-image uv
// of the hit point, interpolated from the hit triangle's corner uvs with Embree's barycentrics.
// One traversal per line collects its kMaxLineHits + 1 hits nearest the lower sample (a line
// holding up to kMaxLineHits is complete), and a traversal from the higher sample, for a line
// with more, its 4 nearest there (field_casts.hpp: coherent packets of 8 rays, rtcIntersect8,
// TBB). A line with more than kMaxLineHits hits keeps the 4 nearest each end.

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

/// `layers` of a layered (version 2) field written from a build: the smallest K that stores every
/// hit of at least kLayerCoverage of the lines (kMaxFieldLayers when none does).
inline constexpr int kAutoLayers = 0;
inline constexpr double kLayerCoverage = 0.999;

/// Peak bytes of building and writing a field with N samples per side: the float nearest-hit
/// table (8 bytes per entry) and the EXR writer's copy (4 bytes per entry for HALF, 8 for
/// FLOAT), the line table and interior hits left out (a few % of it).
size_t field_memory_estimate(int samples_per_side, bool half_precision);

/// Available physical memory in bytes (Linux MemAvailable), 0 when unknown.
size_t available_memory();

/// Checks N against [kMinSamplesPerSide, kMaxSamplesPerSide] and the memory estimate against the
/// available memory. False with an error that states the figures.
bool check_field_size(int samples_per_side, bool half_precision, std::string& error);

struct FieldBuildStats {
  size_t rays = 0;  ///< rays cast (pairs on different faces: both rays of every line)
  size_t hits = 0;  ///< of those, rays that hit the mesh
  /// lines_by_hits[h]: rays with exactly h hits for h <= kMaxLineHits; [kMaxLineHits + 1]: rays
  /// with more (their 4 nearest each end stored).
  std::array<size_t, kMaxLineHits + 2> lines_by_hits{};
  double seconds = 0.0;
};

/// Share of the rays whose every hit fits into `layers` hits per line (1 to kMaxLineHits).
double layer_coverage(const FieldBuildStats& stats, int layers);

/// K of a layered field written from a build: `requested`, or for kAutoLayers the smallest whose
/// layers hold every hit of kLayerCoverage of the lines (kMaxFieldLayers when none does).
int layered_field_layers(const FieldBuildStats& stats, int requested);

/// Builds the compact field of `pm` (the parameterised mesh of `image`, already in `embree`) in
/// the image's box with N samples per side. A hit whose uv falls where the image's bilinear patch
/// reaches into uncovered (padding) texels is moved to the nearby covered patch point closest to
/// the hit (snap_to_covered). `field.source` is left to the caller. False with an error for N out
/// of range or a mesh whose corner uvs do not match its triangles, and with kInterrupted when
/// `control` asked to stop (it hears the casts' progress, stage "field").
bool build_geometry_field(const ParameterizedMesh& pm, const EmbreeMesh& embree,
                          const GeometryImage& image, int samples_per_side, GeometryField& field,
                          std::string& error, FieldBuildStats* stats = nullptr,
                          const JobControl* control = nullptr);

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
/// of the build benchmark): `lines` false, the bare first-hit cast of every ray; true, the
/// traversals of every line of the build. Returns the number of rays that hit.
size_t cast_field_rays(const EmbreeMesh& embree, const Box& box, int samples_per_side,
                       bool lines = false);

}  // namespace gfield
