// Image headers read without decoding (gfield info), and pictures beyond the limits
// refused with their size: a 30000^2 PNG or JPEG was "unknown image type" (stb_image refuses
// what exceeds its own limit in its header check, and stbi_info then tries the other formats).

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "gfield/image.hpp"

namespace gfield {
namespace {

/// A PNG signature and IHDR claiming `width` x `height` 8-bit RGB pixels, nothing after it.
std::string png_header(std::uint32_t width, std::uint32_t height) {
  std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  for (const std::uint32_t v : {width, height})
    for (int shift = 24; shift >= 0; shift -= 8)
      png += char((v >> shift) & 0xFF);
  return png + std::string("\x08\x02\0\0\0", 5) + std::string(4, '\0');
}

/// A JPEG's start, an APP0 segment and a baseline frame header claiming `width` x `height`.
std::string jpeg_header(std::uint16_t width, std::uint16_t height) {
  std::string jpeg("\xFF\xD8\xFF\xE0\0\x10JFIF\0\x01\x01\0\0\x01\0\x01\0\0", 20);
  jpeg += std::string("\xFF\xC0\0\x11\x08", 5);
  jpeg += {char(height >> 8), char(height & 0xFF), char(width >> 8), char(width & 0xFF)};
  return jpeg + std::string("\x03\x01\x22\0\x02\x11\x01\x03\x11\x01", 10);
}

std::string size_error(const std::string& bytes) {
  int width = 0, height = 0;
  std::string error;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  EXPECT_FALSE(decode_image_size("x", data, bytes.size(), width, height, error));
  Image image;
  std::string decode_error;
  EXPECT_FALSE(decode_image("x", data, bytes.size(), image, decode_error));
  EXPECT_EQ(error, decode_error);
  return error;
}

TEST(ImageHeader, TooLargePicturesSayTheirSizeAndTheLimit) {
  for (const std::string& bytes : {png_header(30000, 30000), jpeg_header(30000, 30000)}) {
    const std::string error = size_error(bytes);
    EXPECT_EQ(error.find("unknown image type"), std::string::npos) << error;
    EXPECT_EQ(error.rfind("x: 30000x30000 pixels, more than the limit of 268435456", 0), 0u)
        << error;
  }
  // Claimed sizes are read as the 31-bit numbers PNG allows, not wrapped.
  EXPECT_NE(size_error(png_header(0x80000000u, 1)).find("2147483647x1 pixels"), std::string::npos);
}

TEST(ImageHeader, SizeOfAPictureWithoutDecodingIt) {
  Image image(7, 3, glm::vec3(0.5f));
  std::string png;
  ASSERT_TRUE(encode_png(image, png));
  int width = 0, height = 0;
  std::string error;
  ASSERT_TRUE(decode_image_size("x", reinterpret_cast<const unsigned char*>(png.data()), png.size(),
                                width, height, error))
      << error;
  EXPECT_EQ(width, 7);
  EXPECT_EQ(height, 3);
  // A JPEG's frame header, after its APP0 segment (padded to what 640 x 480 needs at least).
  std::string jpeg = jpeg_header(640, 480);
  jpeg.resize(2000, '\0');
  ASSERT_TRUE(decode_image_size("x", reinterpret_cast<const unsigned char*>(jpeg.data()),
                                jpeg.size(), width, height, error))
      << error;
  EXPECT_EQ(width, 640);
  EXPECT_EQ(height, 480);
}

}  // namespace
}  // namespace gfield
