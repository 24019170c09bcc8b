#include "gfield/exr_io.hpp"

#include <gtest/gtest.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

namespace gfield {
namespace {

namespace fs = std::filesystem;

std::string temp_path(const std::string& name) {
  return (fs::path(GFIELD_TEST_TMP) / ("exr_io_" + name)).string();
}

GeometryImage make_image(int n) {
  GeometryImage image;
  image.size = n;
  image.box = {{-1.5f, 0.25f, 2.0f}, {0.5f, 3.0f, 2.5f}};
  image.source = "unit-test.obj";
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int t = 0; t < n * n; ++t) {
    image.position.push_back({u(rng), u(rng), u(rng)});
    image.normal.push_back(glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 2.0f));
    image.coverage.push_back(t % 3 == 0 ? 0.0f : 1.0f);
  }
  return image;
}

GeometryField make_field(int n) {
  GeometryField field;
  field.samples_per_side = n;
  field.box = {{0, 0, 0}, {1, 2, 3}};
  field.source = "field-test.obj";
  const int side = sample_count(n);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int entry = 0; entry < side; ++entry) {
    for (int exit = 0; exit < side; ++exit) {
      if (face_sample(entry, n).face == face_sample(exit, n).face) {
        field.uv.emplace_back(kFieldNoRay, kFieldNoRay);
      } else if ((entry + exit) % 4 == 0) {
        field.uv.emplace_back(kFieldMiss, kFieldMiss);
      } else {
        field.uv.emplace_back(u(rng), u(rng));
      }
    }
  }
  return field;
}

TEST(ExrIo, GeometryImageRoundTripsInFloatAndHalf) {
  GeometryImage image = make_image(16);
  image.ray_offset = 3.5e-4f;
  for (const ExrPrecision precision : {ExrPrecision::kFloat, ExrPrecision::kHalf}) {
    const std::string path = temp_path("image.gimage.exr");
    std::string error;
    ASSERT_TRUE(save_geometry_image(path, image, precision, error)) << error;
    GeometryImage back;
    ASSERT_TRUE(load_geometry_image(path, back, error)) << error;
    EXPECT_EQ(back.size, 16);
    EXPECT_EQ(back.source, "unit-test.obj");
    EXPECT_EQ(back.box.min, image.box.min);
    EXPECT_EQ(back.box.max, image.box.max);
    EXPECT_EQ(back.ray_offset, image.ray_offset);
    const float normal_tolerance = precision == ExrPrecision::kHalf ? 1e-3f : 0.0f;
    for (size_t t = 0; t < image.position.size(); ++t) {
      ASSERT_EQ(back.position[t], image.position[t]);  // positions are always FLOAT
      ASSERT_NEAR(glm::length(back.normal[t] - image.normal[t]), 0.0f, normal_tolerance);
      ASSERT_EQ(back.coverage[t], image.coverage[t]);
    }
  }
}

/// make_field(n) with `layers` layers: layer l of a pair holds a hit where l < the pair's hits
/// ((entry + exit) % 5 of them), a miss after; "no ray" in every layer.
GeometryField make_layered_field(int n, int layers) {
  const GeometryField first = make_field(n);
  GeometryField field = first;
  field.layers = layers;
  const size_t side = size_t(sample_count(n));
  field.uv.clear();
  for (int layer = 0; layer < layers; ++layer) {
    for (size_t k = 0; k < side * side; ++k) {
      const glm::vec2 uv = first.uv[k];
      const int hits = is_field_hit(uv) ? int((k / side + k % side) % 5) + 1 : 0;
      field.uv.push_back(!is_field_hit(uv) ? uv
                         : layer < hits    ? glm::fract(uv + 0.37f * float(layer))
                                           : glm::vec2(kFieldMiss));
    }
  }
  return field;
}

TEST(ExrIo, LayeredGeometryFieldRoundTrips) {
  const GeometryField field = make_layered_field(3, kMaxFieldLayers);
  const std::string path = temp_path("layers.gfield.exr");
  std::string error;
  ASSERT_TRUE(save_geometry_field(path, field, ExrPrecision::kHalf, error)) << error;
  ExrAssetHeader header;
  ASSERT_TRUE(load_asset_header(path, header, error)) << error;
  EXPECT_EQ(header.version, kFieldFormatVersion);
  EXPECT_EQ(header.layers, kMaxFieldLayers);
  GeometryField back;
  ASSERT_TRUE(load_geometry_field(path, back, error)) << error;
  EXPECT_EQ(back.layers, kMaxFieldLayers);
  ASSERT_EQ(back.uv.size(), field.uv.size());
  for (size_t k = 0; k < field.uv.size(); ++k) {
    ASSERT_NEAR(back.uv[k].x, field.uv[k].x, 5e-4f) << k;
    ASSERT_NEAR(back.uv[k].y, field.uv[k].y, 5e-4f) << k;
  }
  EXPECT_EQ(field_uv(back, 1, 40, 2), field_uv(field, 1, 40, 2));
}

TEST(ExrIo, GeometryFieldRoundTripsInFloatAndHalf) {
  const GeometryField field = make_field(3);
  for (const ExrPrecision precision : {ExrPrecision::kFloat, ExrPrecision::kHalf}) {
    const std::string path = temp_path("field.gfield.exr");
    std::string error;
    ASSERT_TRUE(save_geometry_field(path, field, precision, error)) << error;
    ExrAssetHeader header;
    ASSERT_TRUE(load_asset_header(path, header, error)) << error;
    EXPECT_EQ(header.format, "geometry-field");
    EXPECT_EQ(header.samples_per_side, 3);
    EXPECT_EQ(header.width, 54);
    GeometryField back;
    ASSERT_TRUE(load_geometry_field(path, back, error)) << error;
    EXPECT_EQ(back.samples_per_side, 3);
    EXPECT_EQ(back.source, "field-test.obj");
    EXPECT_EQ(back.box.max, field.box.max);
    // Half floats keep uv to 2^-11 relative; -1 and -2 exactly.
    const float tolerance = precision == ExrPrecision::kHalf ? 5e-4f : 0.0f;
    ASSERT_EQ(back.uv.size(), field.uv.size());
    for (size_t k = 0; k < field.uv.size(); ++k) {
      if (is_field_hit(field.uv[k])) {
        ASSERT_NEAR(back.uv[k].x, field.uv[k].x, tolerance);
        ASSERT_NEAR(back.uv[k].y, field.uv[k].y, tolerance);
      } else {
        ASSERT_EQ(back.uv[k], field.uv[k]);
      }
    }
  }
}

// Writes an EXR with the given attributes and channels (all zeros, FLOAT or `half_channels`
// HALF); gfield.layers when `layers` > 0, gfield.rayOffset when `ray_offset` is not 0.
void write_raw(const std::string& path, int width, int height, const char* format, int version,
               std::initializer_list<const char*> channels, int samples_per_side = 0,
               int layers = 0, std::initializer_list<const char*> half_channels = {},
               float ray_offset = 0.0f) {
  Imf::Header header(width, height);
  if (format) {
    header.insert("gfield.format", Imf::StringAttribute(format));
  }
  header.insert("gfield.version", Imf::IntAttribute(version));
  header.insert("gfield.boxMin", Imf::V3fAttribute({0, 0, 0}));
  header.insert("gfield.boxMax", Imf::V3fAttribute({1, 1, 1}));
  if (samples_per_side) {
    header.insert("gfield.samplesPerSide", Imf::IntAttribute(samples_per_side));
  }
  if (layers) {
    header.insert("gfield.layers", Imf::IntAttribute(layers));
  }
  if (ray_offset != 0.0f) {
    header.insert("gfield.rayOffset", Imf::FloatAttribute(ray_offset));
  }
  std::vector<float> zeros(size_t(width) * size_t(height), 0.0f);
  std::vector<half> half_zeros(zeros.size(), half(0.0f));
  Imf::FrameBuffer fb;
  for (const char* c : half_channels) {
    header.channels().insert(c, Imf::Channel(Imf::HALF));
    fb.insert(c, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(half_zeros.data()), sizeof(half),
                            sizeof(half) * size_t(width)));
  }
  for (const char* c : channels) {
    header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    fb.insert(c, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(zeros.data()), sizeof(float),
                            sizeof(float) * size_t(width)));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(fb);
  file.writePixels(height);
}

void expect_image_error(const std::string& path, const std::string& fragment) {
  GeometryImage image;
  std::string error;
  EXPECT_FALSE(load_geometry_image(path, image, error));
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find(fragment), std::string::npos) << error;
}

// Format version 2: the optional albedo channels round-trip (HALF: 2^-11 relative); an image
// without them loads with no albedo, and a version-1 file (written before albedo) still loads.
TEST(ExrIo, GeometryImageAlbedoIsOptional) {
  GeometryImage image = make_image(8);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (size_t t = 0; t < image.position.size(); ++t) {
    image.albedo.push_back({u(rng), u(rng), u(rng)});
  }
  const std::string path = temp_path("albedo.gimage.exr");
  std::string error;
  for (const ExrPrecision precision : {ExrPrecision::kFloat, ExrPrecision::kHalf}) {
    ASSERT_TRUE(save_geometry_image(path, image, precision, error)) << error;
    GeometryImage back;
    ASSERT_TRUE(load_geometry_image(path, back, error)) << error;
    ASSERT_EQ(back.albedo.size(), image.albedo.size());
    const float tolerance = precision == ExrPrecision::kHalf ? 5e-4f : 0.0f;
    for (size_t t = 0; t < image.albedo.size(); ++t) {
      ASSERT_NEAR(glm::length(back.albedo[t] - image.albedo[t]), 0.0f, tolerance);
    }
  }
  image.albedo.clear();
  ASSERT_TRUE(save_geometry_image(path, image, ExrPrecision::kFloat, error)) << error;
  GeometryImage back;
  ASSERT_TRUE(load_geometry_image(path, back, error)) << error;
  EXPECT_TRUE(back.albedo.empty());
  EXPECT_EQ(sample_albedo(back, glm::vec2(0.3f, 0.6f)), glm::vec3(1.0f));
  write_raw(path, 8, 8, "geometry-image", 1, {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "A"});
  ASSERT_TRUE(load_geometry_image(path, back, error)) << error;
  EXPECT_TRUE(back.albedo.empty());
  EXPECT_EQ(back.ray_offset, kMinRayOffset);  // images written before the ray offset
}

TEST(ExrIo, RejectsBadGeometryImages) {
  const std::string path = temp_path("bad.gimage.exr");
  const auto all = {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "A"};
  write_raw(path, 8, 4, "geometry-image", 1, all);
  expect_image_error(path, "square");
  write_raw(path, 8, 8, "geometry-image", 1, {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z"});
  expect_image_error(path, "missing channel 'A'");
  write_raw(path, 8, 8, "geometry-field", 1, all);
  expect_image_error(path, "wrong format tag");
  write_raw(path, 8, 8, "geometry-image", 3, all);
  expect_image_error(path, "unsupported format version 3");
  write_raw(path, 8, 8, "geometry-image", 1,
            {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "A", "albedo.R", "albedo.G", "albedo.B"});
  expect_image_error(path, "albedo channels in a version-1 geometry image");
  write_raw(path, 8, 8, "geometry-image", 2,
            {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "A", "albedo.R", "albedo.G"});
  expect_image_error(path, "albedo.B");
  write_raw(path, 8, 8, nullptr, 1, all);
  expect_image_error(path, "not a gfield asset");
  for (const float ray_offset : {1e-5f, 0.5f, -1e-3f, std::nanf("")}) {
    write_raw(path, 8, 8, "geometry-image", 2, all, 0, 0, {}, ray_offset);
    expect_image_error(path, "gfield.rayOffset");
  }
  expect_image_error(temp_path("does-not-exist.exr"), "no such file");
  { std::ofstream(path) << "this is not an OpenEXR file"; }
  expect_image_error(path, "not an OpenEXR file");
}

TEST(ExrIo, RejectsBadGeometryFields) {
  const std::string path = temp_path("bad.gfield.exr");
  GeometryField field;
  std::string error;
  write_raw(path, 54, 54, "geometry-field", 1, {"U", "V"}, 4);
  EXPECT_FALSE(load_geometry_field(path, field, error));
  EXPECT_NE(error.find("expected 96x96 for N = 4"), std::string::npos) << error;
  write_raw(path, 54, 54, "geometry-field", 1, {"U"}, 3);
  EXPECT_FALSE(load_geometry_field(path, field, error));
  EXPECT_NE(error.find("missing channel 'V'"), std::string::npos) << error;
  write_raw(path, 54, 54, "geometry-field", 1, {"U", "V"}, 0);
  EXPECT_FALSE(load_geometry_field(path, field, error));
  EXPECT_NE(error.find("samplesPerSide"), std::string::npos) << error;
}

TEST(ExrIo, VersionOneFieldsLoadAsOneLayer) {
  const std::string path = temp_path("v1.gfield.exr");
  write_raw(path, 54, 54, "geometry-field", 1, {"U", "V"}, 3);
  GeometryField field;
  std::string error;
  ASSERT_TRUE(load_geometry_field(path, field, error)) << error;
  EXPECT_EQ(field.layers, 1);
  EXPECT_EQ(field.uv.size(), size_t(54) * 54);
  ExrAssetHeader header;
  ASSERT_TRUE(load_asset_header(path, header, error)) << error;
  EXPECT_EQ(header.layers, 1);
}

void expect_field_error(const std::string& path, const std::string& fragment) {
  GeometryField field;
  std::string error;
  EXPECT_FALSE(load_geometry_field(path, field, error));
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find(fragment), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;  // one line
}

TEST(ExrIo, RejectsFieldsWhoseLayersOrBitDepthDisagreeWithTheHeader) {
  const std::string path = temp_path("bad-layers.gfield.exr");
  write_raw(path, 54, 54, "geometry-field", 2, {"hit0.U", "hit0.V"}, 3, 2);
  expect_field_error(path, "1 hit layers in the channels, but gfield.layers says 2");
  write_raw(path, 54, 54, "geometry-field", 2, {"hit0.U", "hit0.V", "hit1.U", "hit1.V"}, 3, 1);
  expect_field_error(path, "2 hit layers in the channels, but gfield.layers says 1");
  write_raw(path, 54, 54, "geometry-field", 2, {"hit0.U", "hit0.V", "hit1.U", "hit2.V"}, 3, 2);
  expect_field_error(path, "missing channel 'hit1.V'");
  write_raw(path, 54, 54, "geometry-field", 2, {"hit0.U", "hit0.V"}, 3, 0);
  expect_field_error(path, "gfield.layers 0 missing or out of range");
  write_raw(path, 54, 54, "geometry-field", 2, {"hit0.U", "hit0.V"}, 3, kMaxFieldLayers + 1);
  expect_field_error(path, "out of range");
  write_raw(path, 54, 54, "geometry-field", 1, {"U", "V"}, 3, 2);
  expect_field_error(path, "a version-1 field holds one layer");
  write_raw(path, 54, 54, "geometry-field", 2, {"hit0.U", "hit0.V"}, 3, 2, {"hit1.U", "hit1.V"});
  expect_field_error(path, "one bit depth for all layers");
  write_raw(path, 54, 54, "geometry-field", 2, {"hit0.U", "hit0.V"}, 4, 1);
  expect_field_error(path, "expected 96x96 for N = 4");
  write_raw(path, 54, 54, "geometry-field", 3, {"hit0.U", "hit0.V"}, 3, 1);
  expect_field_error(path, "unsupported format version 3 (this build reads versions 1 to 2)");
}

TEST(ExrIo, RejectsFieldsWhoseLayersAreOutOfOrder) {
  // A hit stored after a miss along the same line: the layers are not the line's hits in order.
  GeometryField field = make_layered_field(3, 2);
  const size_t side = size_t(sample_count(3));
  size_t k = 0;
  while (is_field_hit(field.uv[k])) {  // a miss in layer 0 ...
    ++k;
  }
  while (field.uv[k].x != kFieldMiss) {
    ++k;
  }
  field.uv[side * side + k] = glm::vec2(0.5f);  // ... followed by a hit in layer 1
  const std::string path = temp_path("out-of-order.gfield.exr");
  std::string error;
  ASSERT_TRUE(save_geometry_field(path, field, ExrPrecision::kFloat, error)) << error;
  expect_field_error(path, "layer 1 disagrees with layer 0 at entry " + std::to_string(k / side));
}

TEST(ExrIo, TruncatedFileIsAnErrorAndAFailedSaveLeavesNothing) {
  const std::string path = temp_path("truncated.gfield.exr");
  std::string error;
  ASSERT_TRUE(save_geometry_field(path, make_field(4), ExrPrecision::kFloat, error)) << error;
  fs::resize_file(path, fs::file_size(path) / 2);
  GeometryField field;
  EXPECT_FALSE(load_geometry_field(path, field, error));
  EXPECT_NE(error.find(path), std::string::npos) << error;

  // An inconsistent field is refused before anything is written.
  GeometryField bad = make_field(4);
  bad.uv.pop_back();
  const std::string target = temp_path("never-written.gfield.exr");
  fs::remove(target);
  EXPECT_FALSE(save_geometry_field(target, bad, ExrPrecision::kHalf, error));
  EXPECT_FALSE(fs::exists(target));
  // Unwritable destination: an error, and no temporary file left behind.
  EXPECT_FALSE(save_geometry_field("/nonexistent-dir/x.gfield.exr", make_field(2),
                                   ExrPrecision::kHalf, error));
  EXPECT_NE(error.find("/nonexistent-dir/x.gfield.exr"), std::string::npos) << error;
  for (const auto& entry : fs::directory_iterator(GFIELD_TEST_TMP)) {
    const std::string name = entry.path().filename().string();
    EXPECT_FALSE(name.starts_with("exr_io_") && name.find(".tmp-") != std::string::npos) << name;
  }
}

}  // namespace
}  // namespace gfield
