// The GPU storage of geometry fields (gfield/gpu_storage.hpp, the contract's field codes): uvs as
// 8- and 16-bit normalised integers keep the miss and "no ray" codes exact and the uvs to half a
// code step; the byte counts of the figures.

#include "gfield/gpu_storage.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {

GeometryField small_field() {
  GeometryField field;
  field.samples_per_side = 1;  // 6 x 6 pairs
  field.layers = 2;
  const glm::vec2 values[] = {glm::vec2(kFieldNoRay), glm::vec2(kFieldMiss), {0.0f, 1.0f},
                              {0.123456f, 0.987654f}, {0.5f, 0.25f},         {1.0f, 0.0f}};
  for (int k = 0; k < 2 * 36; ++k) {
    field.uv.push_back(values[k % 6]);
  }
  return field;
}

TEST(GpuStorage, CodesKeepMissAndNoRayAndUvsToHalfAStep) {
  const GeometryField field = small_field();
  for (int bits : {8, 16}) {
    const GeometryField q = quantized_field(field, bits);
    const float step = 1.0f / float((1 << bits) - 3);
    for (size_t k = 0; k < field.uv.size(); ++k) {
      if (is_field_hit(field.uv[k])) {
        EXPECT_NEAR(q.uv[k].x, field.uv[k].x, 0.5f * step + 1e-7f) << bits;
        EXPECT_NEAR(q.uv[k].y, field.uv[k].y, 0.5f * step + 1e-7f) << bits;
      } else {
        EXPECT_EQ(q.uv[k], field.uv[k]) << bits;  // -1 and -2 exactly
      }
    }
    EXPECT_EQ(q.uv[2], glm::vec2(0.0f, 1.0f));  // the ends of [0,1] exactly
  }
  EXPECT_EQ(quantized_field(field, 32).uv, field.uv);
}

TEST(GpuStorage, TexelsAreTheCodesTheShaderDecodes) {
  const GeometryField field = small_field();
  const std::vector<uint8_t> rg8 = field_layer_texels(field, 1, 8);
  ASSERT_EQ(rg8.size(), size_t(36 * 2));
  EXPECT_EQ(rg8[0], 254);  // layer 1 starts with "no ray" (k = 36 -> values[0])
  EXPECT_EQ(rg8[2], 255);  // miss
  EXPECT_EQ(rg8[4], 0);
  EXPECT_EQ(rg8[5], 253);
  const std::vector<uint8_t> rg16 = field_layer_texels(field, 0, 16);
  ASSERT_EQ(rg16.size(), size_t(36 * 4));
  uint16_t codes[4];
  std::memcpy(codes, rg16.data() + 4, sizeof(codes));
  EXPECT_EQ(codes[0], 65535);  // miss, both components
  EXPECT_EQ(codes[1], 65535);
  EXPECT_EQ(codes[2], 0);
  EXPECT_EQ(codes[3], 65533);
  // What the texture unit returns for a code, decoded, is the code's uv.
  EXPECT_FLOAT_EQ(gpu::gf_decode_field_component(100.0f / 255.0f, 8), 100.0f / 253.0f);
  EXPECT_EQ(gpu::gf_decode_field_component(1.0f, 16), kFieldMiss);
  EXPECT_EQ(gpu::gf_decode_field_component(65534.0f / 65535.0f, 16), kFieldNoRay);
  const std::vector<uint8_t> floats = field_layer_texels(field, 0, 32);
  ASSERT_EQ(floats.size(), size_t(36 * 8));
  EXPECT_EQ(std::memcmp(floats.data(), field.uv.data(), floats.size()), 0);
}

TEST(GpuStorage, BytesPerAsset) {
  // The figures at N = 24: one RG32F layer 95.6 MB, one RG8 layer 23.9 MB, so four RG8
  // layers fit where one float layer was.
  EXPECT_EQ(field_gpu_bytes(24, 1, 32), size_t(3456) * 3456 * 8);
  EXPECT_EQ(field_gpu_bytes(24, 1, 8), size_t(3456) * 3456 * 2);
  EXPECT_EQ(field_gpu_bytes(24, 4, 8), field_gpu_bytes(24, 1, 32));
  EXPECT_EQ(field_gpu_bytes(24, 2, 16), field_gpu_bytes(24, 1, 32));
  EXPECT_EQ(geometry_image_gpu_bytes(512), size_t(512) * 512 * (16 + 16 + 8));
  EXPECT_TRUE(valid_field_bits(8) && valid_field_bits(16) && valid_field_bits(32));
  EXPECT_FALSE(valid_field_bits(12));
}

}  // namespace
}  // namespace gfield
