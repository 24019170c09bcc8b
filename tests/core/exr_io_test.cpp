#include "gfield/exr_io.hpp"

#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

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
  const GeometryImage image = make_image(16);
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
    const float normal_tolerance = precision == ExrPrecision::kHalf ? 1e-3f : 0.0f;
    for (size_t t = 0; t < image.position.size(); ++t) {
      ASSERT_EQ(back.position[t], image.position[t]);  // positions are always FLOAT
      ASSERT_NEAR(glm::length(back.normal[t] - image.normal[t]), 0.0f, normal_tolerance);
      ASSERT_EQ(back.coverage[t], image.coverage[t]);
    }
  }
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

// Writes an EXR with the given attributes and channels (all FLOAT zeros).
void write_raw(const std::string& path, int width, int height, const char* format, int version,
               std::initializer_list<const char*> channels, int samples_per_side = 0) {
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
  std::vector<float> zeros(size_t(width) * size_t(height), 0.0f);
  Imf::FrameBuffer fb;
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
