#pragma once
// Linear RGB float images (renders, environment maps, metrics) and their files.
//
// Pixel (x, y) is column x, row y; row 0 is the TOP row of the picture, as in PNG and EXR.
// Values are linear radiance (no gamma). PNG files are sRGB-encoded 8-bit: reading converts to
// linear, writing clamps to [0,1] and encodes sRGB. EXR holds linear FLOAT R, G, B; HDR (Radiance)
// is read only.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace gfield {

/// width x height pixels, row-major from the top row: pixels[y * width + x].
struct Image {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> pixels;

  Image() = default;
  Image(int w, int h, glm::vec3 fill = glm::vec3(0.0f))
      : width(w), height(h), pixels(size_t(w) * size_t(h), fill) {}
  bool empty() const { return pixels.empty(); }
  glm::vec3& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const glm::vec3& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

/// Bilinear lookup at continuous coordinates (x, y) in pixels, pixel centres at integer + 0.5.
/// x wraps around (equirectangular longitude) when `wrap_x`, otherwise clamps; y clamps.
glm::vec3 sample_bilinear(const Image& image, float x, float y, bool wrap_x);

/// sRGB transfer functions on one channel (IEC 61966-2-1).
float srgb_to_linear(float v);
float linear_to_srgb(float v);
/// A linear value as the 8-bit sRGB code a PNG stores: clamped to [0, 1], encoded, rounded.
std::uint8_t srgb_byte(float linear);

/// Reads .exr (channels R, G, B; a single Y channel is grey), .hdr (Radiance RGBE), .png (8/16
/// bit) or .jpg/.jpeg (8-bit sRGB -> linear; alpha ignored; grey expands to RGB), at most
/// kMaxPictureFileBytes. False with "FILE: problem".
bool load_image(const std::string& filename, Image& image, std::string& error);

/// The width and height that an image file's header claims, checked as load_image checks them
/// (the limits, the file's size) without decoding its pixels. False with "FILE: problem".
bool load_image_size(const std::string& filename, int& width, int& height, std::string& error);

/// Decodes a PNG, JPEG or HDR image held in memory (an embedded glTF texture): as load_image;
/// `name` stands for the data in errors ("NAME: problem").
bool decode_image(const std::string& name, const unsigned char* bytes, size_t size, Image& image,
                  std::string& error);
/// The width and height its header claims, checked as decode_image checks them.
bool decode_image_size(const std::string& name, const unsigned char* bytes, size_t size, int& width,
                       int& height, std::string& error);

/// `image` as PNG bytes (8-bit sRGB, as save_image writes it); false when the encoder fails.
bool encode_png(const Image& image, std::string& bytes);

/// Writes .exr (FLOAT R, G, B, ZIP compression) or .png (8-bit sRGB, zlib level 1) by the
/// extension, atomically (temporary file + rename). False with "FILE: problem".
bool save_image(const std::string& filename, const Image& image, std::string& error);

}  // namespace gfield
