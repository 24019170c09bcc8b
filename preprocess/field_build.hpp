#pragma once
// Geometry field precomputation (Li et al. 2006, section 2) with Embree 3.
//
// For every pair (entry sample, exit sample) of the 6 N^2 box samples on different faces, the ray
// from the entry point towards the exit point (mesh coordinates, t in [0, 1]) is cast against the
// mesh the geometry image was built from. A hit stores the geometry-image uv of the hit point,
// interpolated from the hit triangle's corner uvs with Embree's barycentrics; a miss stores
// kFieldMiss, a pair on one face kFieldNoRay. Rays are cast in coherent packets (one entry sample,
// 8 consecutive exit samples, rtcIntersect8) with TBB over the entry samples.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gfield/geometry_field.hpp"
#include "gfield/geometry_image.hpp"
#include "preprocess/embree_mesh.hpp"
#include "geometry/parameterized_mesh.hpp"

namespace gfield {

/// Accepted samples per side N (the table has (6N^2)^2 entries: 0.3 MB at N = 4, 1.5 GB at 48).
inline constexpr int kMinSamplesPerSide = 4;
inline constexpr int kMaxSamplesPerSide = 48;

/// Peak bytes of building and writing a field with N samples per side: the float uv table
/// (8 bytes per entry) plus the EXR writer's copy (4 bytes per entry for HALF, 8 for FLOAT).
size_t field_memory_estimate(int samples_per_side, bool half_precision);

/// Available physical memory in bytes (Linux MemAvailable), 0 when unknown.
size_t available_memory();

/// Checks N against [kMinSamplesPerSide, kMaxSamplesPerSide] and the memory estimate against
/// the available memory. False with an error that states both figures.
bool check_field_size(int samples_per_side, bool half_precision, std::string& error);

struct FieldBuildStats {
  size_t rays = 0;  ///< rays cast (pairs on different faces)
  size_t hits = 0;  ///< of those, rays that hit the mesh
  double seconds = 0.0;
};

/// Builds the field of `pm` (the parameterised mesh of `image`, already in `embree`) in the
/// image's box with N samples per side. A hit whose uv falls where the image's bilinear patch
/// reaches into uncovered (padding) texels is moved to the nearby covered patch point closest to
/// the hit (snap_to_covered). `field.source` is left to the caller. False with an error for N out
/// of range or a mesh whose corner uvs do not match its triangles.
bool build_geometry_field(const ParameterizedMesh& pm, const EmbreeMesh& embree,
                          const GeometryImage& image, int samples_per_side, GeometryField& field,
                          std::string& error, FieldBuildStats* stats = nullptr);

/// Which bilinear patches of `image` have all 4 texels covered: (n-1)^2 flags, patch (i, j)
/// (texels i..i+1, j..j+1) at j * (n-1) + i.
std::vector<uint8_t> covered_patches(const GeometryImage& image);

/// `uv` itself when the 2 x 2 texels of its bilinear patch are all covered; otherwise, of `uv`
/// and the points of the fully covered patches within 2 texels, the one whose image position is
/// closest to `hit` (padding texels are copies of other texels, so a lookup there can land far
/// from the surface). `patches` = covered_patches(image).
glm::vec2 snap_to_covered(const GeometryImage& image, const std::vector<uint8_t>& patches,
                          glm::vec2 uv, glm::vec3 hit);

/// Casts exactly the rays and packets of build_geometry_field and stores nothing (the reference
/// of the build benchmark). Returns the number of hits.
size_t cast_field_rays(const EmbreeMesh& embree, const Box& box, int samples_per_side);

}  // namespace gfield
