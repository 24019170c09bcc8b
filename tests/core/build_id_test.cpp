// Build ids (docs/formats.md, "Build id"): SHA-256 against FIPS 180-4 test vectors, the id's
// round trip through both EXR formats, and the readers' refusal of files of two builds.

#include <gtest/gtest.h>

#include "gfield/gpu_contract.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include "gfield/build_id.hpp"
#include "gfield/content_hash.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/field_lookup.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

TEST(ContentHash, Sha256MatchesFips180Vectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // A million 'a's fed in uneven pieces: blocks that straddle update() calls.
  Sha256 h;
  const std::string piece(997, 'a');
  size_t left = 1000000;
  while (left > 0) {
    const size_t n = std::min(left, piece.size());
    h.update(piece.data(), n);
    left -= n;
  }
  EXPECT_EQ(h.hex(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(ContentHash, FileHashIsTheContentsHash) {
  const std::string path =
      (fs::path(gfield::build_paths::test_tmp()) / "content_hash.txt").string();
  { std::ofstream(path, std::ios::binary) << "abc"; }
  std::string hex;
  std::string error;
  ASSERT_TRUE(sha256_file(path, hex, error)) << error;
  EXPECT_EQ(hex, sha256_hex("abc"));
  EXPECT_FALSE(sha256_file(path + ".missing", hex, error));
  EXPECT_NE(error.find("content_hash.txt.missing"), std::string::npos) << error;
  fs::remove(path);
}

GeometryImage tiny_image(const std::string& build_id) {
  GeometryImage image;
  image.size = 2;
  image.source = "m.obj";
  image.build_id = build_id;
  image.position.assign(4, glm::vec3(0.5f));
  image.normal.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
  image.coverage.assign(4, 1.0f);
  return image;
}

GeometryField tiny_field(const std::string& build_id) {
  GeometryField field;
  field.samples_per_side = 1;
  field.source = "m.obj";
  field.build_id = build_id;
  field.nearest.assign(30, glm::vec2(kFieldMiss));
  field.lines.assign(size_t(gpu::gf_field_tiles(1)), 0u);
  return field;
}

TEST(BuildId, RoundTripsThroughBothExrFormats) {
  const std::string image_path =
      (fs::path(gfield::build_paths::test_tmp()) / "build_id.gimage.exr").string();
  const std::string field_path =
      (fs::path(gfield::build_paths::test_tmp()) / "build_id.gfield.exr").string();
  std::string error;
  for (const std::string id : {"0123456789abcdef0123456789abcdef", ""}) {
    ASSERT_TRUE(save_geometry_image(image_path, tiny_image(id), ExrPrecision::kHalf, error));
    ASSERT_TRUE(save_geometry_field(field_path, tiny_field(id), ExrPrecision::kHalf, error));
    GeometryImage image;
    GeometryField field;
    ExrAssetHeader header;
    ASSERT_TRUE(load_geometry_image(image_path, image, error)) << error;
    ASSERT_TRUE(load_geometry_field(field_path, field, error)) << error;
    ASSERT_TRUE(load_asset_header(field_path, header, error)) << error;
    EXPECT_EQ(image.build_id, id);
    EXPECT_EQ(field.build_id, id);
    EXPECT_EQ(header.build_id, id);
  }
  fs::remove(image_path);
  fs::remove(field_path);
}

TEST(BuildId, LookupRefusesAFieldAndAnImageOfTwoBuilds) {
  FieldLookup lookup;
  std::string error;
  const GeometryImage image = tiny_image("aaaa");
  EXPECT_TRUE(make_field_lookup(tiny_field("aaaa"), image, lookup, error)) << error;
  EXPECT_FALSE(make_field_lookup(tiny_field("bbbb"), image, lookup, error));
  EXPECT_NE(error.find("build id bbbb"), std::string::npos) << error;
  EXPECT_NE(error.find("build id aaaa"), std::string::npos) << error;
  // A version-1 field (no id) beside an image with one is a mix as well ...
  EXPECT_FALSE(make_field_lookup(tiny_field(""), image, lookup, error));
  EXPECT_NE(error.find("no build id"), std::string::npos) << error;
  // ... but a version-1 pair without ids still belongs together.
  EXPECT_TRUE(make_field_lookup(tiny_field(""), tiny_image(""), lookup, error)) << error;
}

TEST(BuildId, MessageNamesBothFiles) {
  std::string error;
  EXPECT_TRUE(check_same_build("a.gimage.obj", "x", "a.gimage.exr", "x", error));
  EXPECT_FALSE(check_same_build("a.gimage.obj", "x", "a.gimage.exr", "y", error));
  EXPECT_EQ(error,
            "a.gimage.obj: build id x, but a.gimage.exr has build id y (files of two different "
            "builds; rebuild the asset)");
}

}  // namespace
}  // namespace gfield
