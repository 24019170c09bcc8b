#pragma once
// How assets are stored on the GPU (runtime/gpu_assets): a geometry image as two RGBA32F textures
// (position + coverage, normal); every layer of a geometry field as a normalised-integer RG
// texture of 8 or 16 bits per component (RG8, RG16), or as floats (RG32F, 32). The codes are the
// contract's (shaders/lib/contract.glsl: gf_encode_field_component / gf_decode_field_texel), so the
// CPU can look up exactly what the GPU reads (quantized_field).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gfield/geometry_field.hpp"

namespace gfield {

/// Bits per uv component on the GPU: 8, 16 or 32 (float).
inline bool valid_field_bits(int bits) {
  return bits == 8 || bits == 16 || bits == 32;
}

/// Texels of layer `layer` as uploaded: (6N^2)^2 texels, row = entry, 2 components each of
/// bits / 8 bytes (uint8 codes, uint16 codes or floats), tightly packed.
std::vector<uint8_t> field_layer_texels(const GeometryField& field, int layer, int bits);

/// The field as the GPU reads it at `bits` bits: every uv encoded and decoded by the contract's
/// codes (32: the field itself).
GeometryField quantized_field(const GeometryField& field, int bits);

/// GPU bytes of a field with N samples per side, K layers and `bits` bits per component, stored
/// alone: (6N^2)^2 * K * 2 * bits / 8 (95.6 MB for N = 24, K = 1 at 32 bits; 23.9 MB at 8).
size_t field_gpu_bytes(int samples_per_side, int layers, int bits);

/// GPU bytes of an n x n geometry image stored alone: n^2 * 40 (10.5 MB at n = 512): positions
/// and normals RGBA32F, albedo RGBA16F (runtime/gpu_assets.hpp; white for an image without).
size_t geometry_image_gpu_bytes(int size);

}  // namespace gfield
