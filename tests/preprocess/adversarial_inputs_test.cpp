// Adversarial glTF files, scenes and textures (docs/reliability.md, "Fault and
// adversarial-input campaign"): glTF bounds computed from the data, not trusted; the node-forest
// check linear in the nodes; files an input names confined to its folder (a scene's: its root)
// unless --allow-outside-paths; `gfield info` reading texture headers only, decoding checked
// against the texture budget; messages that name the real reason. Every input is made here.

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "geometry/gltf_checks.hpp"
#include "geometry/scene_file.hpp"
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

const fs::path kDir = test::process_folder("adversarial");

/// A tetrahedron's buffer: 4 float positions in [0, 1]^3, then 12 uint16 indices (72 bytes).
std::string tetrahedron_bin() {
  const float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::uint16_t indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  std::string bin(72, '\0');
  std::memcpy(bin.data(), positions, 48);
  std::memcpy(bin.data() + 48, indices, 24);
  return bin;
}

/// A tetrahedron as glTF JSON whose buffer is `uri` (72 bytes) and whose POSITION accessor
/// declares `min`, `max`.
json tetrahedron_gltf(const std::string& uri, const json& min = {0, 0, 0},
                      const json& max = {1, 1, 1}) {
  json gltf = json::parse(R"({
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}],
    "meshes": [{"name": "tet", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "accessors": [
      {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
      {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                    {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
    "buffers": [{"byteLength": 72}]})");
  gltf["buffers"][0]["uri"] = uri;
  gltf["accessors"][0]["min"] = min;
  gltf["accessors"][0]["max"] = max;
  return gltf;
}

class AdversarialInputs : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { fs::remove_all(kDir); }
};

// glTF bounds are computed, not trusted: POSITION min/max that lie are a warning, and the fitted
// camera frames the data (trusting them framed an empty floor).
TEST_F(AdversarialInputs, LyingAccessorBoundsAreAWarningAndTheCameraFramesTheData) {
  const fs::path dir = kDir / "bounds";
  test::write_file(dir / "tet.bin", tetrahedron_bin());
  test::write_file(dir / "honest.gltf", tetrahedron_gltf("tet.bin").dump());
  test::write_file(dir / "lying.gltf",
                   tetrahedron_gltf("tet.bin", {100, 100, 100}, {101, 101, 101}).dump());
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  ASSERT_TRUE(load_scene_file((dir / "honest.gltf").string(), scene, warnings, error)) << error;
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_TRUE(load_scene_file((dir / "lying.gltf").string(), scene, warnings, error)) << error;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find((dir / "lying.gltf").string() + ": /accessors/0/max"),
            std::string::npos)
      << warnings[0];
  // The data's centre, not the declared one at (100.5, 100.5, 100.5).
  EXPECT_LT(glm::length(scene.camera.target - glm::vec3(0.5f)), 1e-5f);
  // The mesh commands warn too.
  const CliRun info = run_cli("info " + (dir / "lying.gltf").string());
  EXPECT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.err.find("warning: " + (dir / "lying.gltf").string() + ": /accessors/0/max"),
            std::string::npos)
      << info.err;
}

/// A chain of `nodes` nodes, each the child of the one before (`reversed`: of the one after).
json node_chain(size_t nodes, bool reversed) {
  json document = json::object();
  json& list = document["nodes"] = json::array();
  for (size_t n = 0; n < nodes; ++n) {
    json node = json::object();
    if (reversed ? n > 0 : n + 1 < nodes)
      node["children"] = json::array({reversed ? n - 1 : n + 1});
    list.push_back(std::move(node));
  }
  json scene = json::object();
  scene["nodes"] = json::array({reversed ? nodes - 1 : 0});
  document["scenes"] = json::array({scene});
  return document;
}

// `check_node_forest` visits each node a bounded number of times; a walk to the root from every
// node would visit n^2 / 2 on this chain.
TEST_F(AdversarialInputs, NodeForestCheckOfAMillionNodeChainIsLinear) {
  constexpr size_t kNodes = 1'000'000;
  for (const bool reversed : {false, true}) {
    const json chain = node_chain(kNodes, reversed);
    JsonFailure failure;
    std::uint64_t visits = 0;
    EXPECT_TRUE(check_node_forest(chain, failure, visits)) << failure.pointer << failure.what;
    EXPECT_GE(visits, kNodes);
    EXPECT_LE(visits, 4 * kNodes) << (reversed ? "reversed" : "forward") << " chain";
  }
  // A cycle is found with as little work: the last node of the chain made the first's parent.
  json cycle = node_chain(kNodes, false);
  cycle["nodes"][kNodes - 1]["children"] = json::array({0});
  cycle.erase("scenes");
  JsonFailure failure;
  std::uint64_t visits = 0;
  EXPECT_FALSE(check_node_forest(cycle, failure, visits));
  EXPECT_NE(failure.what.find("a cycle of 1000000 nodes"), std::string::npos) << failure.what;
  EXPECT_LE(visits, 4 * kNodes);
}

/// `gfield info` of the tetrahedron with `nodes` as its node list (node 0 holds the mesh).
CliRun info_with_nodes(const std::string& name, const json& nodes) {
  const fs::path dir = kDir / "forest";
  test::write_file(dir / "tet.bin", tetrahedron_bin());
  json gltf = tetrahedron_gltf("tet.bin");
  gltf["nodes"] = nodes;
  gltf.erase("scenes");
  gltf.erase("scene");
  test::write_file(dir / name, gltf.dump());
  return run_cli("info " + (dir / name).string());
}

// Each fault of the node hierarchy is named for what it is: a node that is its own child is not
// "a node with more than one parent".
TEST_F(AdversarialInputs, NodeHierarchyFaultsAreNamedForWhatTheyAre) {
  const std::string file = (kDir / "forest").string();
  const json mesh = json::parse(R"({"mesh": 0})");
  const auto parent_of = [](int child) {
    return json::object({{"children", json::array({child})}});
  };
  json nodes = json::array(
      {mesh, json::object(), json::object(), json::object(), json::object(), parent_of(5)});
  expect_refused(info_with_nodes("own-child.gltf", nodes),
                 {file + "/own-child.gltf:", "/nodes/5/children/0", "node 5 is its own child"});
  nodes = json::array({mesh, parent_of(2), parent_of(3), parent_of(1)});
  expect_refused(info_with_nodes("cycle.gltf", nodes),
                 {file + "/cycle.gltf:", "/nodes/", "a cycle of 3 nodes"});
  nodes = json::array({mesh, parent_of(0), parent_of(0)});
  expect_refused(info_with_nodes("two-parents.gltf", nodes),
                 {file + "/two-parents.gltf:", "/nodes/2/children/0",
                  "node 0 is a child of node 1 and of node 2"});
}

/// `gfield info DIR/inner/tet.gltf` whose buffer is `uri` (its bytes in DIR/outside.bin, and in
/// DIR/inner/link.bin, a symlink to it), with `options`.
CliRun info_of_buffer_uri(const std::string& uri, const std::string& options = "") {
  const fs::path dir = kDir / "gltf-uris";
  test::write_file(dir / "outside.bin", tetrahedron_bin());
  test::write_file(dir / "inner/tet.gltf", tetrahedron_gltf(uri).dump());
  std::error_code ec;
  fs::create_symlink("../outside.bin", dir / "inner/link.bin", ec);
  return run_cli("info " + (dir / "inner/tet.gltf").string() + " " + options);
}

// A buffer URI ../../../../etc/passwd, an absolute path or file:// is refused before the file it
// names is looked at.
TEST_F(AdversarialInputs, GltfUrisStayInTheGltfFilesFolder) {
  const std::string file = (kDir / "gltf-uris/inner/tet.gltf").string() + ":";
  for (const std::string uri : {"../outside.bin", "../../../../../../../../../etc/passwd",
                                "/etc/passwd", "link.bin", "%2E%2E/outside.bin"}) {
    SCOPED_TRACE(uri);
    const std::string shown = uri[0] == '%' ? "../outside.bin" : uri;
    expect_refused(info_of_buffer_uri(uri), {file, "/buffers/0/uri", "\"" + shown + "\""});
  }
  expect_refused(info_of_buffer_uri("file:///etc/passwd"),
                 {file, "/buffers/0/uri", "\"file:///etc/passwd\" is a file: URI"});
  for (const std::string uri : {"../outside.bin", "link.bin"}) {
    const CliRun allowed = info_of_buffer_uri(uri, "--allow-outside-paths");
    EXPECT_EQ(allowed.exit_code, 0) << uri << ": " << allowed.err;
  }
  // Out and back in, through the link: its canonical path is outside.
  expect_refused(info_of_buffer_uri("../inner/link.bin"), {file, "/buffers/0/uri", "leaves"});
  // Image URIs too, checked before any file is touched.
  const fs::path dir = kDir / "gltf-uris";
  test::write_file(dir / "inner/inside.bin", tetrahedron_bin());
  json gltf = tetrahedron_gltf("inside.bin");
  gltf["images"] = json::array({json::object({{"uri", "../texture.png"}})});
  test::write_file(dir / "inner/image.gltf", gltf.dump());
  expect_refused(
      run_cli("info " + (dir / "inner/image.gltf").string()),
      {(dir / "inner/image.gltf").string() + ":", "/images/0/uri", "\"../texture.png\" leaves"});
}

TEST_F(AdversarialInputs, GltfMaterialCountAndIndicesAreCheckedAsOtherFormatsAre) {
  const fs::path dir = kDir / "gltf-limits";
  test::write_file(dir / "tet.bin", tetrahedron_bin());
  json gltf = tetrahedron_gltf("tet.bin");
  gltf["materials"] = json::array();
  for (int m = 0; m < 65537; ++m)
    gltf["materials"].push_back(json::object());
  test::write_file(dir / "many.gltf", gltf.dump());
  expect_refused(run_cli("info " + (dir / "many.gltf").string()),
                 {"many.gltf", "/materials", "65537 materials, more than the limit of 65536"});
  gltf = tetrahedron_gltf("tet.bin");
  gltf["meshes"][0]["primitives"][0]["indices"] = 1.0;
  test::write_file(dir / "float.gltf", gltf.dump());
  expect_refused(run_cli("info " + (dir / "float.gltf").string()),
                 {"float.gltf", "/meshes/0/primitives/0/indices",
                  "1.0 is not an index (an integer from 0) of the accessors"});
}

TEST_F(AdversarialInputs, GltfNodesThatMirrorOrFlattenAreRefusedByEveryCommand) {
  const fs::path dir = kDir / "gltf-scales";
  test::write_file(dir / "tet.bin", tetrahedron_bin());
  for (const char* scale : {"[1, 1, -1]", "[0, 1, 1]"}) {
    SCOPED_TRACE(scale);
    json gltf = tetrahedron_gltf("tet.bin");
    gltf["nodes"][0]["scale"] = json::parse(scale);
    test::write_file(dir / "tet.gltf", gltf.dump());
    const std::string file = (dir / "tet.gltf").string();
    for (const std::string& command :
         {"info " + file, "build " + file + " -o " + (dir / "out").string() + " --size 16"})
      expect_refused(run_cli(command), {file + ": nodes[0]: a mirroring or singular transform"});
    EXPECT_FALSE(fs::exists(dir / "out.report.json"));
  }
}

// A glTF file named without a folder is confined to the working folder like any other.
TEST_F(AdversarialInputs, ABareGltfFileNameStaysInTheWorkingFolder) {
  const fs::path dir = kDir / "bare/inner";
  test::write_file(dir / "tet.gltf", tetrahedron_gltf("../../outside.bin").dump());
  test::write_file(kDir / "outside.bin", tetrahedron_bin());
  const CliRun run = test::run_program(
      "cd " + dir.string() + " && " + std::string(gfield::build_paths::cli()), "info tet.gltf");
  expect_refused(run, {"tet.gltf:", "/buffers/0/uri", "\"../../outside.bin\" leaves"});
}

/// A scene in DIR/project/scenes naming `file` for its mesh, rendered with `options`.
CliRun render_scene_naming(const std::string& file, const std::string& options = "") {
  const fs::path project = kDir / "scene-root/project";
  test::write_file(project / "meshes/tet.obj",
                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n"
                   "f 1 4 3\nf 2 3 4\n");
  std::error_code ec;
  fs::create_symlink("../meshes/tet.obj", project / "scenes/link.obj", ec);
  test::write_file(project / "scenes/s.json",
                   R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]}, "objects": [
        {"shape": "mesh", "file": ")" +
                       file + R"(", "material": {"type": "mirror"}}]})");
  return run_cli("render " + (project / "scenes/s.json").string() + " --size 8x8 -q -o " +
                 (kDir / "scene-root/out.png").string() + " " + options);
}

// A JSON scene's files follow the glTF rule, relative to the scene's root: its own
// folder, or the nearest folder above holding a .gfield-root file (data/ of the checkout).
TEST_F(AdversarialInputs, SceneFilesStayInTheScenesRoot) {
  const fs::path project = kDir / "scene-root/project";
  const std::string scene = (project / "scenes/s.json").string() + ":";
  fs::remove(project / ".gfield-root");
  for (const std::string& name : {std::string("../meshes/tet.obj"), std::string("link.obj"),
                                  (project / "meshes/tet.obj").string()}) {
    SCOPED_TRACE(name);
    expect_refused(render_scene_naming(name), {scene, "objects[0].file", "\"" + name + "\""});
    EXPECT_EQ(render_scene_naming(name, "--allow-outside-paths").exit_code, 0);
  }
  // A path leaving the scene's folder is answered with the marker that would admit it.
  expect_refused(render_scene_naming("../meshes/tet.obj"),
                 {scene, "leaves", "a .gfield-root file in a folder above both"});
  test::write_file(project / ".gfield-root", "");
  EXPECT_EQ(render_scene_naming("../meshes/tet.obj").exit_code, 0);
  EXPECT_EQ(render_scene_naming("link.obj").exit_code, 0);
  expect_refused(render_scene_naming("../../outside.obj"), {scene, "objects[0].file", "leaves"});
  expect_refused(render_scene_naming((project / "meshes/tet.obj").string()),
                 {scene, "is an absolute path"});
  // An environment image is a file the scene names too.
  test::write_file(project / "scenes/env.json",
                   R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
    "environment": {"type": "equirect", "file": "../../env.png"}})");
  expect_refused(run_cli("render " + (project / "scenes/env.json").string() + " --size 8x8 -q -o " +
                         (kDir / "scene-root/env.png").string()),
                 {"env.json:", "environment.file", "\"../../env.png\" leaves"});
}

// An OBJ's material library and its maps are files the mesh names: the same rule.
TEST_F(AdversarialInputs, MaterialLibrariesAndMapsStayInTheMeshFolder) {
  const fs::path dir = kDir / "obj/inner";
  const std::string tet =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl coat\nf 1 3 2\nf 1 2 4\n"
      "f 1 4 3\nf 2 3 4\n";
  test::write_file(dir / "../outside.mtl", "newmtl coat\nKd 1 0 0\n");
  test::write_file(dir / "library.obj", "mtllib ../outside.mtl\n" + tet);
  expect_refused(run_cli("info " + (dir / "library.obj").string()),
                 {(dir / "library.obj").string() + ":", "mtllib", "\"../outside.mtl\" leaves"});
  test::write_file(dir / "inside.mtl", "newmtl coat\nmap_Kd ../../../../etc/passwd\n");
  test::write_file(dir / "map.obj", "mtllib inside.mtl\n" + tet);
  expect_refused(run_cli("info " + (dir / "map.obj").string()),
                 {(dir / "map.obj").string() + ":", "inside.mtl:2", "map_Kd"});
  EXPECT_EQ(run_cli("info " + (dir / "library.obj").string() + " --allow-outside-paths").exit_code,
            0);
}

/// A PNG header claiming `side`^2 RGB pixels, padded to `bytes` (its pixels cannot be decoded).
std::string png_claiming(std::uint32_t side, size_t bytes) {
  std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  for (int k = 0; k < 2; ++k)
    for (int shift = 24; shift >= 0; shift -= 8)
      png += char((side >> shift) & 0xFF);
  png += std::string("\x08\x02\0\0\0", 5) + std::string(4, '\0');  // 8-bit RGB, a CRC
  png.resize(bytes, '\0');
  return png;
}

// A 746 KB PNG claiming 16000^2 pixels costs `gfield info` no decoding: info reads the header (the
// pixels here cannot even be decoded); decoding checks the claimed size against the texture budget
// before it starts.
TEST_F(AdversarialInputs, InfoReadsTextureHeadersAndDecodingChecksTheBudget) {
  const fs::path dir = kDir / "budget";
  test::write_file(dir / "big.png", png_claiming(16000, 40000));
  test::write_file(dir / "tet.mtl", "newmtl coat\nmap_Kd big.png\n");
  test::write_file(dir / "tet.obj",
                   "mtllib tet.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nusemtl coat\n"
                   "f 1/1 3/1 2/1\nf 1/1 2/1 4/1\nf 1/1 4/1 3/1\nf 2/1 3/1 4/1\n");
  test::write_file(dir / "tet.bin", tetrahedron_bin());
  json gltf = tetrahedron_gltf("tet.bin");
  gltf["images"] = json::parse(R"([{"uri": "big.png"}])");
  gltf["textures"] = json::parse(R"([{"source": 0}])");
  gltf["materials"] =
      json::parse(R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
  gltf["meshes"][0]["primitives"][0]["material"] = 0;
  test::write_file(dir / "tet.gltf", gltf.dump());
  for (const char* mesh : {"tet.obj", "tet.gltf"}) {
    SCOPED_TRACE(mesh);
    const CliRun info = run_cli("info --json " + (dir / mesh).string());
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const json textures = json::parse(info.out)["appearance"]["textures"];
    ASSERT_EQ(textures.size(), 1u);
    EXPECT_EQ(textures[0]["width"], 16000);
    EXPECT_EQ(textures[0]["height"], 16000);
    const std::string texture =
        mesh == std::string("tet.obj") ? (dir / "big.png").string() : (dir / "tet.gltf").string();
    expect_refused(run_cli("image " + (dir / mesh).string() + " --size 16 -o " +
                           (dir / "x.gimage.exr").string()),
                   {texture, "16000x16000 pixels", "beyond the texture budget of 2.15 GB"});
    EXPECT_FALSE(fs::exists(dir / "x.gimage.exr"));
  }
}

// A 30000^2 PNG is named with its size and the limit, not as stb_image's "unknown image type"
// (its own size limit, reported so by stbi_info).
TEST_F(AdversarialInputs, TooLargeImagesSayTheirSizeAndTheLimit) {
  const fs::path dir = kDir / "too-large";
  test::write_file(dir / "huge.png", png_claiming(30000, 1000));
  test::write_file(dir / "s.json", R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
    "environment": {"type": "equirect", "file": "huge.png"}})");
  expect_refused(run_cli("render " + (dir / "s.json").string() + " --size 8x8 -q -o " +
                         (dir / "out.png").string()),
                 {(dir / "huge.png").string(), "30000x30000 pixels, more than the limit"});
}

/// load_scene_file of a glTF tetrahedron whose material is `material`: its error.
std::string gltf_material_error(const json& material) {
  const fs::path dir = kDir / "materials";
  test::write_file(dir / "tet.bin", tetrahedron_bin());
  json gltf = tetrahedron_gltf("tet.bin");
  gltf["materials"] = json::array({material});
  gltf["meshes"][0]["primitives"][0]["material"] = 0;
  test::write_file(dir / "tet.gltf", gltf.dump());
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  EXPECT_FALSE(load_scene_file((dir / "tet.gltf").string(), scene, warnings, error));
  return error;
}

// JSON and glTF scenes take one range of the index of refraction, [1e-6, 1e6], as documented,
// and say so with the value.
TEST_F(AdversarialInputs, GltfRangesAreTheJsonScenesRanges) {
  std::string error = gltf_material_error(json::parse(R"({"extensions": {
      "KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_ior": {"ior": 1e7}}})"));
  EXPECT_NE(error.find("KHR_materials_ior.ior must be in [1e-6, 1e6] (is 1e+07)"),
            std::string::npos)
      << error;
  const fs::path dir = kDir / "lights";
  test::write_file(dir / "tet.bin", tetrahedron_bin());
  json gltf = tetrahedron_gltf("tet.bin");
  gltf["extensions"] = json::parse(
      R"({"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 1000000.4}]}})");
  gltf["nodes"][0]["extensions"] = json::parse(R"({"KHR_lights_punctual": {"light": 0}})");
  test::write_file(dir / "tet.gltf", gltf.dump());
  Scene scene;
  std::vector<std::string> warnings;
  EXPECT_FALSE(load_scene_file((dir / "tet.gltf").string(), scene, warnings, error));
  EXPECT_NE(error.find("lights[0]: intensity must be in [0, 1e6] (is 1000000.4)"),
            std::string::npos)
      << error;
}

/// load_scene_file of two glass spheres of radius 1, the second at `x`: its warnings.
std::vector<std::string> two_glass_spheres(double x) {
  const fs::path file = kDir / "dielectrics/s.json";
  test::write_file(file, R"({"camera": {"position": [0, 0, 9], "target": [0, 0, 0]}, "objects": [
    {"name": "left", "shape": "sphere", "material": {"type": "dielectric", "ior": 1.5}},
    {"name": "right", "shape": "sphere", "transform": {"translate": [)" +
                             std::to_string(x) + R"(, 0, 0]},
     "material": {"type": "dielectric", "ior": "water"}}]})");
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  EXPECT_TRUE(load_scene_file(file.string(), scene, warnings, error)) << error;
  return warnings;
}

// Overlapping dielectrics, which docs/scenes.md forbids, are named.
// Bounding boxes can intersect where the solids do not, so it is a warning.
TEST_F(AdversarialInputs, DielectricsWhoseBoxesIntersectAreAWarning) {
  const std::vector<std::string> overlapping = two_glass_spheres(1.5);
  ASSERT_EQ(overlapping.size(), 1u);
  EXPECT_NE(overlapping[0].find("'left' (object 0) and 'right' (object 1)"), std::string::npos)
      << overlapping[0];
  EXPECT_NE(overlapping[0].find("must not overlap"), std::string::npos) << overlapping[0];
  EXPECT_TRUE(two_glass_spheres(2.5).empty());
}

}  // namespace
}  // namespace gfield
