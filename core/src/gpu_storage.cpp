#include "gfield/gpu_storage.hpp"

#include <cstring>

#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {

template <class T>
void encode_layer(const glm::vec2* uv, size_t count, int bits, uint8_t* bytes) {
  T* out = reinterpret_cast<T*>(bytes);
  for (size_t k = 0; k < count; ++k) {
    out[2 * k] = T(gpu::gf_encode_field_component(uv[k].x, bits));
    out[2 * k + 1] = T(gpu::gf_encode_field_component(uv[k].y, bits));
  }
}

}  // namespace

std::vector<uint8_t> field_layer_texels(const GeometryField& field, int layer, int bits) {
  const size_t count = field_layer_size(field);
  const glm::vec2* uv = field.uv.data() + size_t(layer) * count;
  std::vector<uint8_t> bytes(count * 2 * size_t(bits / 8));
  if (bits == 8) {
    encode_layer<uint8_t>(uv, count, bits, bytes.data());
  } else if (bits == 16) {
    encode_layer<uint16_t>(uv, count, bits, bytes.data());
  } else {
    std::memcpy(bytes.data(), uv, bytes.size());
  }
  return bytes;
}

GeometryField quantized_field(const GeometryField& field, int bits) {
  GeometryField out = field;
  if (bits >= 32) {
    return out;
  }
  const float top = float((1 << bits) - 1);
  for (glm::vec2& uv : out.uv) {
    // What the texture unit returns for the code, decoded as the shader does.
    const glm::vec2 texel(gpu::gf_encode_field_component(uv.x, bits) / top,
                          gpu::gf_encode_field_component(uv.y, bits) / top);
    uv = gpu::gf_decode_field_texel(texel, bits);
  }
  return out;
}

size_t field_gpu_bytes(int samples_per_side, int layers, int bits) {
  const size_t side = size_t(sample_count(samples_per_side));
  return side * side * size_t(layers) * 2 * size_t(bits / 8);
}

size_t geometry_image_gpu_bytes(int size) {
  constexpr size_t kAlbedoTexelBytes = 8;  // RGBA16F
  return size_t(size) * size_t(size) * (2 * sizeof(glm::vec4) + kAlbedoTexelBytes);
}

}  // namespace gfield
