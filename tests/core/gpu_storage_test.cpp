// The GPU storage of geometry fields (gfield/gpu_storage.hpp, the contract's field codes): uvs as
// 8- and 16-bit normalised integers keep the miss and "no ray" codes exact and the uvs to half a
// code step; interior hits packed into words as the shader unpacks them; the byte counts of the
// issue's figures.

#include "gfield/gpu_storage.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {

const glm::vec2 kValues[] = {
    glm::vec2(kFieldMiss), {0.0f, 1.0f}, {0.123456f, 0.987654f}, {0.5f, 0.25f}, {1.0f, 0.0f}};

/// N = 1 (6 x 5 nearest hits) holding kValues in turn, and three interior hits.
GeometryField small_field() {
  GeometryField field;
  field.samples_per_side = 1;
  field.layers = 2;
  for (int k = 0; k < 30; ++k) {
    field.nearest.push_back(kValues[k % 5]);
  }
  field.interior = {kValues[1], kValues[2], kValues[3]};
  field.lines.assign(size_t(gpu::gf_field_tiles(1)), 0u);
  return field;
}

TEST(GpuStorage, CodesKeepMissAndUvsToHalfAStep) {
  const GeometryField field = small_field();
  for (int bits : {8, 16}) {
    const GeometryField q = quantized_field(field, bits);
    const float step = 1.0f / float((1 << bits) - 3);
    for (size_t k = 0; k < field.nearest.size(); ++k) {
      if (is_field_hit(field.nearest[k])) {
        EXPECT_NEAR(q.nearest[k].x, field.nearest[k].x, 0.5f * step + 1e-7f) << bits;
        EXPECT_NEAR(q.nearest[k].y, field.nearest[k].y, 0.5f * step + 1e-7f) << bits;
      } else {
        EXPECT_EQ(q.nearest[k], field.nearest[k]) << bits;  // -1 exactly
      }
    }
    EXPECT_EQ(q.nearest[1], glm::vec2(0.0f, 1.0f));  // the ends of [0,1] exactly
    EXPECT_NEAR(q.interior[1].x, field.interior[1].x, 0.5f * step + 1e-7f) << bits;
  }
  EXPECT_EQ(quantized_field(field, 32).nearest, field.nearest);
  // The contract's "no ray" code decodes exactly too.
  EXPECT_EQ(gpu::gf_decode_field_code(gpu::gf_encode_field_component(kFieldNoRay, 8), 8),
            kFieldNoRay);
}

TEST(GpuStorage, TexelsAreTheCodesTheShaderDecodes) {
  const GeometryField field = small_field();
  const std::vector<uint8_t> rg8 = field_nearest_texels(field, 8);
  ASSERT_EQ(rg8.size(), size_t(30 * 2));
  EXPECT_EQ(rg8[0], 255);  // miss
  EXPECT_EQ(rg8[2], 0);
  EXPECT_EQ(rg8[3], 253);
  const std::vector<uint8_t> rg16 = field_nearest_texels(field, 16);
  ASSERT_EQ(rg16.size(), size_t(30 * 4));
  uint16_t codes[4];
  std::memcpy(codes, rg16.data(), sizeof(codes));
  EXPECT_EQ(codes[0], 65535);  // miss, both components
  EXPECT_EQ(codes[1], 65535);
  EXPECT_EQ(codes[2], 0);
  EXPECT_EQ(codes[3], 65533);
  // What the texture unit returns for a code, decoded, is the code's uv.
  EXPECT_FLOAT_EQ(gpu::gf_decode_field_component(100.0f / 255.0f, 8), 100.0f / 253.0f);
  EXPECT_EQ(gpu::gf_decode_field_component(1.0f, 16), kFieldMiss);
  EXPECT_EQ(gpu::gf_decode_field_component(65534.0f / 65535.0f, 16), kFieldNoRay);
  const std::vector<uint8_t> floats = field_nearest_texels(field, 32);
  ASSERT_EQ(floats.size(), size_t(30 * 8));
  EXPECT_EQ(std::memcmp(floats.data(), field.nearest.data(), floats.size()), 0);
}

// Interior hits as gpu_assets.glsl's gf_field_interior_texel reads them: 8 bits, two hits of two
// codes each per word (the first in the low half, u below v); 16 bits, a hit per word; 32 bits,
// the floats' bits.
TEST(GpuStorage, InteriorHitsArePackedAsTheShaderUnpacksThem) {
  const GeometryField field = small_field();
  const std::vector<uint32_t> w8 = field_interior_words(field, 8);
  ASSERT_EQ(w8.size(), size_t(2));
  EXPECT_EQ(w8[0] & 0xFFu, 0u);                   // hit 0: u = 0
  EXPECT_EQ((w8[0] >> 8) & 0xFFu, 253u);          // v = 1
  EXPECT_EQ((w8[0] >> 16) & 0xFFu, 31u);          // hit 1: u = round(0.123456 * 253)
  EXPECT_EQ(w8[1] & 0xFFFFu, 127u | (63u << 8));  // hit 2: (0.5, 0.25); the high half unused
  EXPECT_EQ(w8[1] >> 16, 0u);
  const std::vector<uint32_t> w16 = field_interior_words(field, 16);
  ASSERT_EQ(w16.size(), size_t(3));
  EXPECT_EQ(w16[0], 65533u << 16);
  const std::vector<uint32_t> w32 = field_interior_words(field, 32);
  ASSERT_EQ(w32.size(), size_t(6));
  float v = 0.0f;
  std::memcpy(&v, &w32[3], sizeof(float));
  EXPECT_EQ(v, kValues[2].y);
}

TEST(GpuStorage, BytesPerAsset) {
  // The layered figures at N = 24: one RG32F layer 95.6 MB, one RG8 layer 23.9 MB, so four RG8
  // layers fit where one float layer was.
  EXPECT_EQ(layered_field_gpu_bytes(24, 1, 32), size_t(3456) * 3456 * 8);
  EXPECT_EQ(layered_field_gpu_bytes(24, 1, 8), size_t(3456) * 3456 * 2);
  EXPECT_EQ(layered_field_gpu_bytes(24, 4, 8), layered_field_gpu_bytes(24, 1, 32));
  // The compact field: its nearest hits (6 x 5 per N^2 x N^2), its line words and interior hits.
  const GeometryField field = small_field();
  EXPECT_EQ(field_gpu_bytes(field, 8), size_t(30 * 2 + (field.lines.size() + 2) * 4));
  EXPECT_EQ(field_gpu_bytes(field, 16), size_t(30 * 4 + (field.lines.size() + 3) * 4));
  EXPECT_EQ(field_gpu_bytes(field, 32), size_t(30 * 8 + (field.lines.size() + 6) * 4));
  EXPECT_EQ(geometry_image_gpu_bytes(512), size_t(512) * 512 * (16 + 16 + 8));
  EXPECT_TRUE(valid_field_bits(8) && valid_field_bits(16) && valid_field_bits(32));
  EXPECT_FALSE(valid_field_bits(12));
}

}  // namespace
}  // namespace gfield
