#include "gfield/gpu_storage.hpp"

#include <cstring>

#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {

template <class T>
void encode_texels(const glm::vec2* uv, size_t count, int bits, uint8_t* bytes) {
  T* out = reinterpret_cast<T*>(bytes);
  for (size_t k = 0; k < count; ++k) {
    out[2 * k] = T(gpu::gf_encode_field_component(uv[k].x, bits));
    out[2 * k + 1] = T(gpu::gf_encode_field_component(uv[k].y, bits));
  }
}

/// What the GPU reads for `uv` stored at `bits` bits (< 32).
glm::vec2 quantized(glm::vec2 uv, int bits) {
  return glm::vec2(gpu::gf_decode_field_code(gpu::gf_encode_field_component(uv.x, bits), bits),
                   gpu::gf_decode_field_code(gpu::gf_encode_field_component(uv.y, bits), bits));
}

uint32_t code(float component, int bits) {
  return uint32_t(gpu::gf_encode_field_component(component, bits));
}

}  // namespace

std::vector<uint8_t> field_nearest_texels(const GeometryField& field, int bits) {
  const size_t count = field.nearest.size();
  std::vector<uint8_t> bytes(count * 2 * size_t(bits / 8));
  if (bits == 8) {
    encode_texels<uint8_t>(field.nearest.data(), count, bits, bytes.data());
  } else if (bits == 16) {
    encode_texels<uint16_t>(field.nearest.data(), count, bits, bytes.data());
  } else if (!bytes.empty()) {
    std::memcpy(bytes.data(), field.nearest.data(), bytes.size());
  }
  return bytes;
}

std::vector<uint32_t> field_interior_words(const GeometryField& field, int bits) {
  std::vector<uint32_t> words;
  const std::vector<glm::vec2>& hits = field.interior;
  if (bits == 8) {
    words.assign((hits.size() + 1) / 2, 0u);
    for (size_t i = 0; i < hits.size(); ++i) {
      const uint32_t pair = code(hits[i].x, 8) | (code(hits[i].y, 8) << 8);
      words[i / 2] |= pair << (16 * (i % 2));
    }
  } else if (bits == 16) {
    for (const glm::vec2& uv : hits) {
      words.push_back(code(uv.x, 16) | (code(uv.y, 16) << 16));
    }
  } else if (!hits.empty()) {
    words.resize(2 * hits.size());
    std::memcpy(words.data(), hits.data(), words.size() * sizeof(uint32_t));
  }
  return words;
}

GeometryField quantized_field(const GeometryField& field, int bits) {
  GeometryField out = field;
  if (bits >= 32) {
    return out;
  }
  for (glm::vec2& uv : out.nearest) {
    uv = quantized(uv, bits);
  }
  for (glm::vec2& uv : out.interior) {
    uv = quantized(uv, bits);
  }
  return out;
}

size_t field_gpu_bytes(const GeometryField& field, int bits) {
  const size_t interior_words =
      bits == 8 ? (field.interior.size() + 1) / 2 : field.interior.size() * size_t(bits / 16);
  return field.nearest.size() * 2 * size_t(bits / 8) +
         (field.lines.size() + interior_words) * sizeof(uint32_t);
}

size_t layered_field_gpu_bytes(int samples_per_side, int layers, int bits) {
  const size_t side = size_t(sample_count(samples_per_side));
  return side * side * size_t(layers) * 2 * size_t(bits / 8);
}

size_t geometry_image_gpu_bytes(int size) {
  constexpr size_t kAlbedoTexelBytes = 8;  // RGBA16F
  return size_t(size) * size_t(size) * (2 * sizeof(glm::vec4) + kAlbedoTexelBytes);
}

}  // namespace gfield
