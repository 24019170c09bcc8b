#include "gfield/exr_io.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "gfield/field_lines.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

std::string temp_path(const std::string& name) {
  return (fs::path(gfield::build_paths::test_tmp()) / ("exr_io_" + name)).string();
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

/// A layered table of N = n (as versions 1 and 2 hold it: `layers` tables of (6N^2)^2 uvs,
/// index (layer * S + entry) * S + exit), as a build makes it: "no ray" on one face; else a line
/// of (entry + exit) % 5 + 1 random hits (none where (entry + exit) % 4 == 0), the first
/// `layers` of them from each end, misses after them.
std::vector<glm::vec2> make_layered_table(int n, int layers) {
  const size_t side = size_t(sample_count(n));
  std::vector<glm::vec2> table(side * side * size_t(layers));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const auto at = [&](int layer, size_t entry, size_t exit) -> glm::vec2& {
    return table[(size_t(layer) * side + entry) * side + exit];
  };
  for (size_t low = 0; low < side; ++low) {
    for (size_t high = low; high < side; ++high) {
      const bool no_ray = face_sample(int(low), n).face == face_sample(int(high), n).face;
      // The line's hits from `low`; the ray from `high` meets them in reverse.
      const int count = no_ray || (low + high) % 4 == 0 ? 0 : int((low + high) % 5) + 1;
      std::vector<glm::vec2> hits;
      for (int k = 0; k < count; ++k) {
        hits.emplace_back(u(rng), u(rng));
      }
      for (int layer = 0; layer < layers; ++layer) {
        const bool hit = layer < count;
        at(layer, low, high) = no_ray ? glm::vec2(kFieldNoRay)
                               : hit  ? hits[size_t(layer)]
                                      : glm::vec2(kFieldMiss);
        at(layer, high, low) = no_ray ? glm::vec2(kFieldNoRay)
                               : hit  ? hits[size_t(count - 1 - layer)]
                                      : glm::vec2(kFieldMiss);
      }
    }
  }
  return table;
}

/// The compact field of make_layered_table(n, layers).
GeometryField make_field(int n, int layers = kMaxFieldLayers) {
  GeometryField field;
  field.samples_per_side = n;
  field.box = {{0, 0, 0}, {1, 2, 3}};
  field.source = "field-test.obj";
  compact_layered_table(make_layered_table(n, layers), layers, field);
  return field;
}

/// Expects field_uv of `a` and `b` to agree on every pair and the first `layers` layers, within
/// `tolerance` (half floats keep uv to 2^-11 relative; -1 and -2 exactly).
void expect_same_hits(const GeometryField& a, const GeometryField& b, int layers, float tolerance) {
  const int side = field_side(a);
  for (int entry = 0; entry < side; ++entry) {
    for (int exit = 0; exit < side; ++exit) {
      for (int layer = 0; layer < layers; ++layer) {
        const glm::vec2 x = field_uv(a, entry, exit, layer), y = field_uv(b, entry, exit, layer);
        if (is_field_hit(x)) {
          ASSERT_NEAR(x.x, y.x, tolerance) << entry << " " << exit << " " << layer;
          ASSERT_NEAR(x.y, y.y, tolerance) << entry << " " << exit << " " << layer;
        } else {
          ASSERT_EQ(x, y) << entry << " " << exit << " " << layer;
        }
      }
    }
  }
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

TEST(ExrIo, LayeredGeometryFieldRoundTrips) {
  const GeometryField field = make_field(3);
  const std::string path = temp_path("layers.gfield.exr");
  std::string error;
  ASSERT_TRUE(save_layered_geometry_field(path, field, kMaxFieldLayers, ExrPrecision::kHalf, error))
      << error;
  ExrAssetHeader header;
  ASSERT_TRUE(load_asset_header(path, header, error)) << error;
  EXPECT_EQ(header.version, kLayeredFieldVersion);
  EXPECT_EQ(header.layers, kMaxFieldLayers);
  EXPECT_EQ(header.width, 54);
  GeometryField back;
  ASSERT_TRUE(load_geometry_field(path, back, error)) << error;
  EXPECT_EQ(back.layers, kMaxFieldLayers);
  expect_same_hits(field, back, kMaxFieldLayers, 5e-4f);
}

TEST(ExrIo, GeometryFieldRoundTripsInFloatAndHalf) {
  const GeometryField field = make_field(3);
  ASSERT_FALSE(field.interior.empty());  // lines of 3 and more hits: the line table is used
  for (const ExrPrecision precision : {ExrPrecision::kFloat, ExrPrecision::kHalf}) {
    const std::string path = temp_path("field.gfield.exr");
    std::string error;
    ASSERT_TRUE(save_geometry_field(path, field, precision, error)) << error;
    ExrAssetHeader header;
    ASSERT_TRUE(load_asset_header(path, header, error)) << error;
    EXPECT_EQ(header.format, "geometry-field");
    EXPECT_EQ(header.version, kFieldFormatVersion);
    EXPECT_EQ(header.samples_per_side, 3);
    EXPECT_EQ(header.width, 45);
    GeometryField back;
    ASSERT_TRUE(load_geometry_field(path, back, error)) << error;
    EXPECT_EQ(back.samples_per_side, 3);
    EXPECT_EQ(back.layers, field.layers);
    EXPECT_EQ(back.source, "field-test.obj");
    EXPECT_EQ(back.box.max, field.box.max);
    EXPECT_EQ(back.lines, field.lines);
    ASSERT_EQ(back.interior.size(), field.interior.size());
    expect_same_hits(field, back, kMaxLineHits, precision == ExrPrecision::kHalf ? 5e-4f : 0.0f);
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
  EXPECT_EQ(field.nearest.size(), size_t(54) * 45);
  ExrAssetHeader header;
  ASSERT_TRUE(load_asset_header(path, header, error)) << error;
  EXPECT_EQ(header.layers, 1);
}

/// Writes `table` (make_layered_table's layout, FLOAT) as a version-2 field of N = n.
void write_layered(const std::string& path, int n, int layers,
                   const std::vector<glm::vec2>& table) {
  const int side = sample_count(n);
  Imf::Header header(side, side);
  header.insert("gfield.format", Imf::StringAttribute("geometry-field"));
  header.insert("gfield.version", Imf::IntAttribute(2));
  header.insert("gfield.boxMin", Imf::V3fAttribute({0, 0, 0}));
  header.insert("gfield.boxMax", Imf::V3fAttribute({1, 1, 1}));
  header.insert("gfield.samplesPerSide", Imf::IntAttribute(n));
  header.insert("gfield.layers", Imf::IntAttribute(layers));
  Imf::FrameBuffer fb;
  const size_t count = size_t(side) * size_t(side);
  for (int layer = 0; layer < layers; ++layer) {
    for (int c = 0; c < 2; ++c) {
      const std::string name = "hit" + std::to_string(layer) + (c == 0 ? ".U" : ".V");
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      char* base = const_cast<char*>(reinterpret_cast<const char*>(&table[size_t(layer) * count]));
      fb.insert(name, Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(glm::vec2),
                                 sizeof(glm::vec2) * size_t(side)));
    }
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(fb);
  file.writePixels(side);
}

// A version-2 file as the layered builds wrote it loads into the compact field with the same
// hits from both ends of every line.
TEST(ExrIo, VersionTwoFieldsLoadWithEveryStoredHit) {
  const int n = 3, layers = 3;
  const std::vector<glm::vec2> table = make_layered_table(n, layers);
  const std::string path = temp_path("v2.gfield.exr");
  write_layered(path, n, layers, table);
  GeometryField field;
  std::string error;
  ASSERT_TRUE(load_geometry_field(path, field, error)) << error;
  EXPECT_EQ(field.layers, layers);
  const int side = sample_count(n);
  for (int entry = 0; entry < side; ++entry) {
    for (int exit = 0; exit < side; ++exit) {
      for (int layer = 0; layer < layers; ++layer) {
        const size_t k =
            (size_t(layer) * size_t(side) + size_t(entry)) * size_t(side) + size_t(exit);
        ASSERT_EQ(field_uv(field, entry, exit, layer), table[k]) << entry << " " << exit;
      }
    }
  }
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
  write_raw(path, 45, 54, "geometry-field", 3, {"hit0.U", "hit0.V"}, 3, 1);
  expect_field_error(path, "holds the channels hit.U, hit.V and line");
  write_raw(path, 54, 54, "geometry-field", 4, {"hit0.U", "hit0.V"}, 3, 1);
  expect_field_error(path, "unsupported format version 4 (this build reads versions 1 to 3)");
}

TEST(ExrIo, RejectsFieldsWhoseLayersAreOutOfOrder) {
  // A hit stored after a miss along the same line: the layers are not the line's hits in order.
  std::vector<glm::vec2> table = make_layered_table(3, 2);
  const size_t side = size_t(sample_count(3));
  size_t k = 0;
  while (table[k].x != kFieldMiss) {  // a miss in layer 0 ...
    ++k;
  }
  table[side * side + k] = glm::vec2(0.5f);  // ... followed by a hit in layer 1
  const std::string path = temp_path("out-of-order.gfield.exr");
  write_layered(path, 3, 2, table);
  expect_field_error(path, "layer 1 disagrees with layer 0 at entry " + std::to_string(k / side));
}

// Version 3: a line table that disagrees with itself, its size or the interior hits is refused in
// one line naming the file, never read past its end.
TEST(ExrIo, RejectsCompactFieldsWhoseLineTableDisagrees) {
  const GeometryField good = make_field(3);
  const std::string path = temp_path("bad-lines.gfield.exr");
  const auto expect_refused = [&](const GeometryField& bad, const std::string& fragment) {
    std::string error;
    ASSERT_TRUE(save_geometry_field(path, bad, ExrPrecision::kFloat, error)) << error;
    SCOPED_TRACE(fragment);
    expect_field_error(path, fragment);
  };
  const size_t tiles =
      size_t(std::find_if(good.lines.begin(), good.lines.end(), [](uint32_t w) { return w != 0; }) -
             good.lines.begin());
  const uint32_t record = good.lines[tiles];
  GeometryField bad = good;
  bad.lines[tiles] += 4;  // a tile's record elsewhere than the next in tile order
  expect_refused(bad, "(records in tile order, 4 words each)");
  bad = good;
  bad.lines[record] = bad.lines[record + 1] = 0;
  expect_refused(bad, "its record marks no line");
  bad = good;
  bad.lines[record + 3] += 1;  // interior hits that start past where the tiles before end
  expect_refused(bad, "first interior hit");
  bad = good;
  bad.lines.back() = (bad.lines.back() & 0xFFFF0000u) | 9u;  // a count above 8
  expect_refused(bad, "hits at offset");
  bad = good;
  bad.lines.pop_back();
  expect_refused(bad, "its entries run past the table's");
  bad = good;
  bad.lines.push_back(0u);
  expect_refused(bad, "words and");
  bad = good;
  bad.interior.push_back(glm::vec2(0.5f));
  expect_refused(bad, "interior hits, its entries need");
  bad = good;
  bad.nearest[7] = glm::vec2(1.5f, 0.5f);
  expect_refused(bad, "is neither a uv in [0,1]^2 nor a miss");
  bad = good;
  bad.interior[0] = glm::vec2(-1.0f);
  expect_refused(bad, "interior hit 0 (-1");
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
  bad.nearest.pop_back();
  const std::string target = temp_path("never-written.gfield.exr");
  fs::remove(target);
  EXPECT_FALSE(save_geometry_field(target, bad, ExrPrecision::kHalf, error));
  EXPECT_FALSE(fs::exists(target));
  // Unwritable destination: an error, and no temporary file left behind.
  EXPECT_FALSE(save_geometry_field("/nonexistent-dir/x.gfield.exr", make_field(2),
                                   ExrPrecision::kHalf, error));
  EXPECT_NE(error.find("/nonexistent-dir/x.gfield.exr"), std::string::npos) << error;
  // This process's temporary files (NAME.tmp-PID-N): other tests' processes write theirs into the
  // same folder at the same time.
  const std::string own = ".tmp-" + std::to_string(getpid()) + "-";
  for (const auto& entry : fs::directory_iterator(gfield::build_paths::test_tmp())) {
    const std::string name = entry.path().filename().string();
    EXPECT_FALSE(name.starts_with("exr_io_") && name.find(own) != std::string::npos) << name;
  }
}

}  // namespace
}  // namespace gfield
