#pragma once
// How assets are stored on the GPU (runtime/gpu_assets): a geometry image as two RGBA32F textures
// (position + coverage, normal); a geometry field's nearest-hit table as a normalised-integer RG
// texture of 8 or 16 bits per component (RG8, RG16), or as floats (RG32F, 32), and its line
// table and interior hits (the same codes, packed into words) in a storage buffer. The codes are
// the contract's (shaders/lib/contract.glsl: gf_encode_field_component / gf_decode_field_code),
// so the CPU can look up exactly what the GPU reads (quantized_field).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gfield/geometry_field.hpp"

namespace gfield {

/// Bits per uv component on the GPU: 8, 16 or 32 (float).
inline bool valid_field_bits(int bits) {
  return bits == 8 || bits == 16 || bits == 32;
}

/// The nearest-hit table as uploaded: 6N^2 rows of 5N^2 texels, 2 components each of bits / 8
/// bytes (uint8 codes, uint16 codes or floats), tightly packed.
std::vector<uint8_t> field_nearest_texels(const GeometryField& field, int bits);

/// The interior hits as the storage buffer holds them after the line table: at 8 bits two hits
/// per word (each 16 bits: the u code, then the v code above it; the first hit in the low half),
/// at 16 bits one per word (u in the low half), at 32 bits two words each (the floats' bits).
std::vector<uint32_t> field_interior_words(const GeometryField& field, int bits);

/// The field as the GPU reads it at `bits` bits: every uv encoded and decoded by the contract's
/// codes (32: the field itself).
GeometryField quantized_field(const GeometryField& field, int bits);

/// GPU bytes of `field` stored alone at `bits` bits per component: the nearest-hit table, the
/// line table and the interior hits (N = 24: 19.9 MB + the lines at 8 bits).
size_t field_gpu_bytes(const GeometryField& field, int bits);

/// GPU bytes of a layered (version 2) field with N samples per side and K layers, stored alone
/// at `bits` bits: (6N^2)^2 * K * 2 * bits / 8 (95.6 MB for N = 24, K = 4 at 8 bits).
size_t layered_field_gpu_bytes(int samples_per_side, int layers, int bits);

/// GPU bytes of an n x n geometry image stored alone: n^2 * 40 (10.5 MB at n = 512): positions
/// and normals RGBA32F, albedo RGBA16F (runtime/gpu_assets.hpp; white for an image without).
size_t geometry_image_gpu_bytes(int size);

}  // namespace gfield
