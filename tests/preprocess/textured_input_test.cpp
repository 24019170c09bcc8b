// Bad input, through the gfield commands: a texture that is not an image, uvs that are
// NaN, glTF files with out-of-range indices, a zero-length or truncated .glb, an unsupported
// primitive mode, a missing .bin: exit 2, one stderr line naming the file, nothing on stdout, no
// output file. A missing texture is a warning naming it, exit 0, and mid-grey albedo.

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "gfield/exr_io.hpp"
#include "gfield/geometry_image.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/refusal.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CliRun;
using test::expect_refused;
using test::run_cli;

const fs::path kDir = test::process_folder("textured_input");

/// A tetrahedron with texture coordinates and a material `mtl` (its map_Kd: `texture`).
const char* kTetrahedronObj =
    "mtllib tet.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\n"
    "usemtl coat\nf 1/1 3/3 2/2\nf 1/1 2/2 4/3\nf 1/1 4/3 3/2\nf 2/1 3/2 4/3\n";

/// `gfield image FILE` and `gfield info FILE` refuse `file`; the image leaves no file behind.
void expect_image_refused(const fs::path& file, const std::string& what) {
  SCOPED_TRACE(what);
  expect_refused(run_cli("info " + file.string()), {file.string()}, what + " (info)");
  const fs::path out = kDir / "out";
  fs::remove_all(out);
  fs::create_directories(out);
  expect_refused(
      run_cli("image " + file.string() + " -o " + (out / "x.gimage.exr").string() + " --size 16"),
      {file.string()}, what + " (image)");
  EXPECT_TRUE(fs::is_empty(out)) << what << ": image left files behind";
}

/// A tetrahedron as a .gltf with its buffer in tet.bin (4 float positions, 12 uint16 indices).
json tetrahedron_gltf(const fs::path& folder) {
  const float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::uint16_t indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  std::string bin(72, '\0');
  std::memcpy(bin.data(), positions, 48);
  std::memcpy(bin.data() + 48, indices, 24);
  test::write_file(folder / "tet.bin", bin);
  return json::parse(R"({
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}],
    "meshes": [{"name": "tet", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1,
                                               "mode": 4}]}],
    "accessors": [
      {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
       "min": [0, 0, 0], "max": [1, 1, 1]},
      {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                    {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
    "buffers": [{"uri": "tet.bin", "byteLength": 72}]})");
}

class TexturedInput : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { fs::remove_all(kDir); }
};

TEST_F(TexturedInput, MissingTextureIsAWarningAndMidGrey) {
  const fs::path dir = kDir / "missing-texture";
  test::write_file(dir / "tet.obj", kTetrahedronObj);
  test::write_file(dir / "tet.mtl", "newmtl coat\nKd 1 1 1\nmap_Kd nowhere.png\n");
  const fs::path out = dir / "tet.gimage.exr";
  const CliRun run =
      run_cli("image " + (dir / "tet.obj").string() + " -o " + out.string() + " --size 32");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("nowhere.png"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("warning"), std::string::npos) << run.err;
  GeometryImage image;
  std::string error;
  ASSERT_TRUE(load_geometry_image(out.string(), image, error)) << error;
  ASSERT_EQ(image.albedo.size(), image.position.size());
  for (size_t t = 0; t < image.albedo.size(); ++t) {
    if (image.coverage[t] > 0.0f) {
      ASSERT_NEAR(image.albedo[t].r, 0.5f, 1e-3f);
      ASSERT_NEAR(image.albedo[t].g, 0.5f, 1e-3f);
      ASSERT_NEAR(image.albedo[t].b, 0.5f, 1e-3f);
    }
  }
}

TEST_F(TexturedInput, TextureThatIsNotAnImageIsRefused) {
  const fs::path dir = kDir / "not-an-image";
  test::write_file(dir / "tet.obj", kTetrahedronObj);
  test::write_file(dir / "tet.mtl", "newmtl coat\nKd 1 1 1\nmap_Kd coat.png\n");
  test::write_file(dir / "coat.png", "this is text, not a PNG\n");
  expect_image_refused(dir / "tet.obj", "texture that is not an image");
}

TEST_F(TexturedInput, NanTextureCoordinatesAreRefused) {
  const fs::path dir = kDir / "nan-uv";
  std::string obj = kTetrahedronObj;
  obj.replace(obj.find("vt 1 0"), 6, "vt nan 0");
  test::write_file(dir / "tet.obj", obj);
  test::write_file(dir / "tet.mtl", "newmtl coat\nKd 1 1 1\n");
  expect_image_refused(dir / "tet.obj", "NaN uv");
}

TEST_F(TexturedInput, DamagedGltfFilesAreRefused) {
  const fs::path dir = kDir / "gltf";
  const json good = tetrahedron_gltf(dir);
  test::write_file(dir / "good.gltf", good.dump());
  const CliRun ok = run_cli("info " + (dir / "good.gltf").string());
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const std::pair<const char*, std::function<void(json&)>> cases[] = {
      {"accessor-view", [](json& d) { d["accessors"][1]["bufferView"] = 7; }},
      {"indices-accessor", [](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 9; }},
      {"view-buffer", [](json& d) { d["bufferViews"][0]["buffer"] = 3; }},
      {"view-beyond-buffer", [](json& d) { d["bufferViews"][1]["byteLength"] = 400; }},
      {"node-mesh", [](json& d) { d["nodes"][0]["mesh"] = -1; }},
      {"points-mode", [](json& d) { d["meshes"][0]["primitives"][0]["mode"] = 0; }},
      {"lines-mode", [](json& d) { d["meshes"][0]["primitives"][0]["mode"] = 1; }},
      {"missing-bin", [](json& d) { d["buffers"][0]["uri"] = "missing.bin"; }},
  };
  for (const auto& [name, damage] : cases) {
    json doc = good;
    damage(doc);
    const fs::path file = dir / (std::string(name) + ".gltf");
    test::write_file(file, doc.dump());
    expect_image_refused(file, name);
  }
}

TEST_F(TexturedInput, ZeroLengthAndTruncatedGlbAreRefused) {
  const fs::path dir = kDir / "glb";
  test::write_file(dir / "empty.glb", "");
  expect_image_refused(dir / "empty.glb", "zero-length .glb");
  std::ifstream in(fs::path(gfield::build_paths::data_dir()) / "scenes/textured-mirror.glb",
                   std::ios::binary);
  const std::string glb((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(glb.size(), 1000u);
  for (const size_t keep : {size_t(11), size_t(40), glb.size() / 2, glb.size() - 1}) {
    const fs::path file = dir / ("truncated-" + std::to_string(keep) + ".glb");
    test::write_file(file, glb.substr(0, keep));
    expect_image_refused(file, "truncated .glb");
    const fs::path picture = dir / "render.png";
    expect_refused(run_cli("render " + file.string() + " --size 8x8 -q -o " + picture.string()),
                   {file.string()}, "render of a truncated .glb");
    EXPECT_FALSE(fs::exists(picture));
  }
}

}  // namespace
}  // namespace gfield
