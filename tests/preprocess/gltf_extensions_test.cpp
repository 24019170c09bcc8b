// glTF as the ecosystem writes it: extensionsRequired refused when gfield does not
// implement the extension, KHR_mesh_quantization, KHR_texture_transform,
// KHR_draco_mesh_compression and EXT_meshopt_compression, each on a hand-made file whose
// expected mesh is worked out by hand from the extension's specification (Draco and meshopt data
// made with the libraries' own encoders from a known tetrahedron), and the checks in front of
// the decoders.

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include "geometry/glb_container.hpp"
#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/scene_file.hpp"
#include "gfield/image.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/test_files.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CliRun;
using test::run_cli;

const fs::path kDir = test::process_folder("gltf_ext");

template <class T>
std::string bytes_of(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

/// The tetrahedron of these tests: positions, indices (outward), one uv per vertex.
const std::vector<float> kPositions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
const std::vector<std::uint16_t> kIndices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

/// A glTF document of one mesh of one primitive (attributes and indices given), one node.
json one_mesh(const json& attributes, int indices) {
  json d = {{"asset", {{"version", "2.0"}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"mesh", 0}}}},
            {"meshes", {{{"primitives", {{{"attributes", attributes}, {"indices", indices}}}}}}}};
  return d;
}

/// load_mesh of `file` (mesh `part`) with its appearance; false with `error`.
bool read_mesh(const fs::path& file, TriangleMesh& mesh, MeshAppearance& appearance,
               std::string& error, const std::string& part = "") {
  std::vector<std::string> warnings;
  return load_mesh(MeshSource{file.string(), part}, mesh, &appearance, warnings, error);
}

/// A tetrahedron whose buffer is tet.bin in `dir` (positions, then indices).
json tetrahedron(const fs::path& dir) {
  test::write_file(dir / "tet.bin", bytes_of(kPositions) + bytes_of(kIndices));
  json d = one_mesh({{"POSITION", 0}}, 1);
  d["accessors"] = {
      {{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
      {{"bufferView", 1}, {"componentType", 5123}, {"count", 12}, {"type", "SCALAR"}}};
  d["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                      {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 24}}};
  d["buffers"] = {{{"uri", "tet.bin"}, {"byteLength", 72}}};
  return d;
}

TEST(GltfExtensions, AnUnimplementedRequiredExtensionIsRefusedNamingIt) {
  const fs::path dir = kDir / "required";
  json d = tetrahedron(dir);
  d["extensionsUsed"] = {"KHR_mesh_quantization", "EXT_gfield_unheard_of"};
  d["extensionsRequired"] = {"KHR_mesh_quantization", "EXT_gfield_unheard_of"};
  test::write_file(dir / "s.gltf", d.dump());
  const std::string file = (dir / "s.gltf").string();
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  EXPECT_FALSE(load_scene_file(file, scene, warnings, error));
  EXPECT_EQ(error.rfind(file + ":", 0), 0u) << error;
  EXPECT_NE(error.find("/extensionsRequired/1: the file requires extension EXT_gfield_unheard_of"),
            std::string::npos)
      << error;
  TriangleMesh mesh;
  EXPECT_FALSE(load_mesh(file, mesh, error));
  EXPECT_NE(error.find("EXT_gfield_unheard_of"), std::string::npos) << error;
  // Every command: one line, exit 2, no picture.
  const CliRun run = run_cli("render " + file + " --size 8x8 -o " + (dir / "out.png").string());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_NE(run.err.find(file), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("EXT_gfield_unheard_of"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
  // Required and implemented: it loads.
  d["extensionsRequired"] = {"KHR_mesh_quantization"};
  test::write_file(dir / "s.gltf", d.dump());
  EXPECT_TRUE(load_scene_file(file, scene, warnings, error)) << error;
}

TEST(GltfExtensions, AnUnimplementedExtensionUsedButNotRequiredIsAWarningNamingWhere) {
  const fs::path dir = kDir / "used";
  json d = tetrahedron(dir);
  d["extensionsUsed"] = {"KHR_materials_clearcoat", "EXT_mesh_gpu_instancing"};
  d["materials"] = {{{"name", "coat"},
                     {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
                     {"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}}}}}}};
  d["meshes"][0]["primitives"][0]["material"] = 0;
  d["nodes"][0]["extensions"] = {{"EXT_mesh_gpu_instancing", {{"attributes", json::object()}}}};
  test::write_file(dir / "s.gltf", d.dump());
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  ASSERT_TRUE(load_scene_file((dir / "s.gltf").string(), scene, warnings, error)) << error;
  std::string all;
  for (const std::string& w : warnings)
    all += w + "\n";
  EXPECT_NE(all.find("materials[0] 'coat': extension KHR_materials_clearcoat is ignored"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("/nodes/0/extensions/EXT_mesh_gpu_instancing: extension "
                     "EXT_mesh_gpu_instancing is ignored"),
            std::string::npos)
      << all;
}

/// The tetrahedron with quantised attributes: mesh 0 positions SHORT normalized, mesh 1
/// UNSIGNED_SHORT integers under a node scaled by 0.5; both uvs UNSIGNED_BYTE normalized.
json quantized(const fs::path& dir) {
  // Vertex attributes are aligned to 4 bytes: VEC3 of shorts at a stride of 8.
  const std::vector<std::int16_t> normalized = {0, 0,     0, 0, 32767, 0, 0,      0,
                                                0, 32767, 0, 0, 0,     0, -32768, 0};
  const std::vector<std::uint16_t> integers = {0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0};
  const std::vector<std::uint8_t> uvs = {0, 0, 0, 0, 255, 0, 0, 0, 0, 255, 0, 0, 51, 102, 0, 0};
  test::write_file(dir / "q.bin",
                   bytes_of(normalized) + bytes_of(integers) + bytes_of(uvs) + bytes_of(kIndices));
  json d = one_mesh({{"POSITION", 0}, {"TEXCOORD_0", 2}}, 3);
  d["meshes"].push_back(one_mesh({{"POSITION", 1}, {"TEXCOORD_0", 2}}, 3)["meshes"][0]);
  d["nodes"].push_back({{"mesh", 1}, {"scale", {0.5, 0.5, 0.5}}});
  d["scenes"][0]["nodes"] = {0, 1};
  d["extensionsUsed"] = {"KHR_mesh_quantization"};
  d["extensionsRequired"] = {"KHR_mesh_quantization"};
  d["accessors"] = {
      {{"bufferView", 0},
       {"componentType", 5122},
       {"normalized", true},
       {"count", 4},
       {"type", "VEC3"},
       {"min", {0, 0, -32768}},
       {"max", {32767, 32767, 0}}},
      {{"bufferView", 1},
       {"componentType", 5123},
       {"count", 4},
       {"type", "VEC3"},
       {"min", {0, 0, 0}},
       {"max", {2, 2, 2}}},
      {{"bufferView", 2},
       {"componentType", 5121},
       {"normalized", true},
       {"count", 4},
       {"type", "VEC2"}},
      {{"bufferView", 3}, {"componentType", 5123}, {"count", 12}, {"type", "SCALAR"}}};
  d["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 32}, {"byteStride", 8}},
                      {{"buffer", 0}, {"byteOffset", 32}, {"byteLength", 32}, {"byteStride", 8}},
                      {{"buffer", 0}, {"byteOffset", 64}, {"byteLength", 16}, {"byteStride", 4}},
                      {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 24}}};
  d["buffers"] = {{{"uri", "q.bin"}, {"byteLength", 104}}};
  return d;
}

TEST(GltfExtensions, QuantizedAttributesReadAsTheSpecificationSays) {
  const fs::path dir = kDir / "quantized";
  json d = quantized(dir);
  test::write_file(dir / "q.gltf", d.dump());
  TriangleMesh mesh;
  MeshAppearance a;
  std::string error;
  // SHORT normalized: c / 32767, at least -1 (glTF 2.0, "Animations"): -32768 reads -1.
  ASSERT_TRUE(read_mesh(dir / "q.gltf", mesh, a, error, "#0")) << error;
  const std::vector<glm::dvec3> expected = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  ASSERT_EQ(mesh.positions.size(), 4u);
  for (size_t v = 0; v < 4; ++v)
    EXPECT_EQ(mesh.positions[v], expected[v]) << v;
  // UNSIGNED_BYTE normalized: c / 255; gfield's v runs up (1 - v): (51, 102) -> (0.2, 0.6).
  const std::vector<glm::vec2> uv = {{0, 1}, {1, 1}, {0, 0}, {0.2f, 0.6f}};
  ASSERT_EQ(a.corner_uv.size(), 12u);
  for (size_t c = 0; c < 12; ++c) {
    EXPECT_NEAR(a.corner_uv[c].x, uv[kIndices[c]].x, 1e-6) << c;
    EXPECT_NEAR(a.corner_uv[c].y, uv[kIndices[c]].y, 1e-6) << c;
  }
  // Integers as they are, placed by their node: 2 * 0.5.
  ASSERT_TRUE(read_mesh(dir / "q.gltf", mesh, a, error)) << error;
  ASSERT_EQ(mesh.positions.size(), 8u);
  const std::vector<glm::dvec3> placed = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (size_t v = 0; v < 4; ++v)
    EXPECT_EQ(mesh.positions[4 + v], placed[v]) << v;
  // The declared min and max of a normalized accessor are its stored integers: no warning.
  Scene scene;
  std::vector<std::string> warnings;
  ASSERT_TRUE(load_scene_file((dir / "q.gltf").string(), scene, warnings, error)) << error;
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  // Without KHR_mesh_quantization, glTF allows floats only for POSITION.
  d.erase("extensionsUsed");
  d.erase("extensionsRequired");
  test::write_file(dir / "plain.gltf", d.dump());
  EXPECT_FALSE(read_mesh(dir / "plain.gltf", mesh, a, error, "#0"));
  EXPECT_NE(error.find("meshes[0].primitives[0]: POSITION: accessor 0 is SHORT normalized, which "
                       "glTF allows only with KHR_mesh_quantization"),
            std::string::npos)
      << error;
}

/// A 2 x 2 PNG.
std::string tiny_png() {
  Image image(2, 2);
  std::string png;
  EXPECT_TRUE(encode_png(image, png));
  while (png.size() % 4 != 0)
    png += '\0';
  return png;
}

TEST(GltfExtensions, TextureTransformMapsTheTexCoordSetItNames) {
  // The extension's own example: offset (0, 1), rotation pi/2, scale 0.5 maps uv (0, 0), (1, 0),
  // (0, 1), (1, 1) to (0, 1), (0, 0.5), (0.5, 1), (0.5, 0.5) ("the lower left quadrant of the
  // image, rotated clockwise 90 degrees"); in gfield's uvs (v up) (0, 0), (0, 0.5), (0.5, 0),
  // (0.5, 0.5). Its texCoord 1 overrides the textureInfo's 0: TEXCOORD_0 is a decoy.
  const fs::path dir = kDir / "transform";
  const std::vector<float> decoy = {0.9f, 0.9f, 0.9f, 0.9f, 0.9f, 0.9f, 0.9f, 0.9f};
  const std::vector<float> set1 = {0, 0, 1, 0, 0, 1, 1, 1};
  const std::string png = tiny_png();
  const std::string bin =
      bytes_of(kPositions) + bytes_of(kIndices) + bytes_of(decoy) + bytes_of(set1) + png;
  json d = one_mesh({{"POSITION", 0}, {"TEXCOORD_0", 2}, {"TEXCOORD_1", 3}}, 1);
  d["extensionsUsed"] = {"KHR_texture_transform"};
  d["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                    {{"bufferView", 1}, {"componentType", 5123}, {"count", 12}, {"type", "SCALAR"}},
                    {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
                    {{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}}};
  d["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                      {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 24}},
                      {{"buffer", 0}, {"byteOffset", 72}, {"byteLength", 32}},
                      {{"buffer", 0}, {"byteOffset", 104}, {"byteLength", 32}},
                      {{"buffer", 0}, {"byteOffset", 136}, {"byteLength", png.size()}}};
  d["buffers"] = {{{"byteLength", bin.size()}}};
  d["images"] = {{{"bufferView", 4}, {"mimeType", "image/png"}}};
  d["textures"] = {{{"source", 0}}};
  d["materials"] = {{{"pbrMetallicRoughness",
                      {{"metallicFactor", 0.0},
                       {"baseColorTexture",
                        {{"index", 0},
                         {"texCoord", 0},
                         {"extensions",
                          {{"KHR_texture_transform",
                            {{"offset", {0.0, 1.0}},
                             {"rotation", 1.5707963267948966},
                             {"scale", {0.5, 0.5}},
                             {"texCoord", 1}}}}}}}}}}};
  d["meshes"][0]["primitives"][0]["material"] = 0;
  test::write_file(dir / "t.glb", glb_bytes(d.dump(), bin));
  TriangleMesh mesh;
  MeshAppearance a;
  std::string error;
  ASSERT_TRUE(read_mesh(dir / "t.glb", mesh, a, error)) << error;
  const std::vector<glm::vec2> expected = {{0, 0}, {0, 0.5f}, {0.5f, 0}, {0.5f, 0.5f}};
  ASSERT_EQ(a.corner_uv.size(), 12u);
  for (size_t c = 0; c < 12; ++c) {
    EXPECT_NEAR(a.corner_uv[c].x, expected[kIndices[c]].x, 1e-6) << c;
    EXPECT_NEAR(a.corner_uv[c].y, expected[kIndices[c]].y, 1e-6) << c;
  }
  // A transform that leaves the limits of texture coordinates is refused, naming it.
  d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
   ["KHR_texture_transform"]["scale"] = {1e9, 1};
  test::write_file(dir / "far.glb", glb_bytes(d.dump(), bin));
  EXPECT_FALSE(read_mesh(dir / "far.glb", mesh, a, error));
  EXPECT_NE(error.find("baseColorTexture.KHR_texture_transform.scale"), std::string::npos) << error;
  // A texCoord set the primitive lacks reads the texture at (0, 0): a warning naming the place.
  d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
   ["KHR_texture_transform"] = {{"texCoord", 2}};
  test::write_file(dir / "set2.glb", glb_bytes(d.dump(), bin));
  std::vector<std::string> warnings;
  ASSERT_TRUE(load_mesh(MeshSource{(dir / "set2.glb").string(), ""}, mesh, &a, warnings, error))
      << error;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("set2.glb: meshes[0].primitives[0]: its material's base colour "
                             "texture reads TEXCOORD_2, which the primitive lacks"),
            std::string::npos)
      << warnings[0];
}

/// A corner of a triangle: position and gfield uv.
using Corner = std::array<float, 5>;
using Triangle = std::array<Corner, 3>;

/// Triangles as corner lists, each rotated to start at its smallest corner, sorted: equal for
/// two meshes that differ only in vertex order and numbering.
std::vector<Triangle> triangle_set(const TriangleMesh& mesh, const std::vector<glm::vec2>& uv) {
  std::vector<Triangle> out;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 p = mesh.positions[size_t(mesh.triangles[f][k])];
      t[size_t(k)] = {float(p.x), float(p.y), float(p.z), uv[3 * f + size_t(k)].x,
                      uv[3 * f + size_t(k)].y};
    }
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The tetrahedron with a uv per corner (face f, corner k: (f / 4, k / 2)) Draco-encoded
/// (edgebreaker, lossless floats), the number of points Draco decodes it to, and its ids.
std::string draco_tetrahedron(int& points, int& position_id, int& uv_id) {
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(4);
  const int position =
      builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int uv = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  for (int f = 0; f < 4; ++f) {
    const float* p[3];
    float t[3][2];
    for (int k = 0; k < 3; ++k) {
      p[k] = &kPositions[3 * kIndices[size_t(3 * f + k)]];
      t[k][0] = float(f) / 4.0f;
      t[k][1] = float(k) / 2.0f;
    }
    builder.SetAttributeValuesForFace(position, draco::FaceIndex(f), p[0], p[1], p[2]);
    builder.SetAttributeValuesForFace(uv, draco::FaceIndex(f), t[0], t[1], t[2]);
  }
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  position_id = int(mesh->attribute(position)->unique_id());
  uv_id = int(mesh->attribute(uv)->unique_id());
  draco::Encoder encoder;
  draco::EncoderBuffer buffer;
  EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());
  draco::DecoderBuffer in;
  in.Init(buffer.data(), buffer.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&in);
  EXPECT_TRUE(decoded.ok());
  points = int(decoded.value()->num_points());
  return std::string(buffer.data(), buffer.size());
}

/// A .glb of the Draco tetrahedron (`compressed`, `points` points), positions and uvs floats.
std::string draco_glb(const std::string& compressed, int points, int position_id, int uv_id) {
  json d = one_mesh({{"POSITION", 1}, {"TEXCOORD_0", 2}}, 0);
  d["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  d["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  d["meshes"][0]["primitives"][0]["extensions"] = {
      {"KHR_draco_mesh_compression",
       {{"bufferView", 0}, {"attributes", {{"POSITION", position_id}, {"TEXCOORD_0", uv_id}}}}}};
  d["accessors"] = {{{"componentType", 5123}, {"count", 12}, {"type", "SCALAR"}},
                    {{"componentType", 5126}, {"count", points}, {"type", "VEC3"}},
                    {{"componentType", 5126}, {"count", points}, {"type", "VEC2"}}};
  d["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", compressed.size()}}};
  d["buffers"] = {{{"byteLength", compressed.size()}}};
  return glb_bytes(d.dump(), compressed);
}

TEST(GltfExtensions, DracoPrimitivesDecodeToTheMeshTheyEncode) {
  const fs::path dir = kDir / "draco";
  int points = 0, position_id = -1, uv_id = -1;
  const std::string compressed = draco_tetrahedron(points, position_id, uv_id);
  test::write_file(dir / "d.glb", draco_glb(compressed, points, position_id, uv_id));
  TriangleMesh mesh;
  MeshAppearance a;
  std::string error;
  ASSERT_TRUE(read_mesh(dir / "d.glb", mesh, a, error)) << error;
  // The source: the same corners (Draco renumbers vertices and may reorder faces).
  TriangleMesh source;
  std::vector<glm::vec2> source_uv;
  for (int f = 0; f < 4; ++f) {
    for (int k = 0; k < 3; ++k) {
      const size_t v = kIndices[size_t(3 * f + k)];
      source.positions.emplace_back(kPositions[3 * v], kPositions[3 * v + 1],
                                    kPositions[3 * v + 2]);
      source_uv.emplace_back(float(f) / 4.0f, 1.0f - float(k) / 2.0f);  // gfield's v
    }
    source.triangles.emplace_back(3 * f, 3 * f + 1, 3 * f + 2);
  }
  EXPECT_EQ(triangle_set(mesh, a.corner_uv), triangle_set(source, source_uv));

  // What gfield checks around the decoder, each named at the extension's pointer.
  const std::string pointer = "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression";
  test::write_file(dir / "count.glb", draco_glb(compressed, points + 1, position_id, uv_id));
  EXPECT_FALSE(read_mesh(dir / "count.glb", mesh, a, error));
  EXPECT_NE(error.find(pointer + ": attributes.POSITION: Draco decoded " + std::to_string(points) +
                       " points"),
            std::string::npos)
      << error;
  test::write_file(dir / "truncated.glb", draco_glb(compressed.substr(0, compressed.size() / 2),
                                                    points, position_id, uv_id));
  EXPECT_FALSE(read_mesh(dir / "truncated.glb", mesh, a, error));
  EXPECT_NE(error.find(pointer + ": "), std::string::npos) << error;
  test::write_file(dir / "id.glb", draco_glb(compressed, points, position_id, 77));
  EXPECT_FALSE(read_mesh(dir / "id.glb", mesh, a, error));
  EXPECT_NE(error.find("attributes.TEXCOORD_0: no Draco attribute of that id"), std::string::npos)
      << error;
}

/// A .glb of the tetrahedron with EXT_meshopt_compression: positions (ATTRIBUTES, stride 12)
/// and indices (TRIANGLES, 16 bits) in buffer 0, decoded into fallback buffer 1. `cut` bytes
/// are taken off the compressed indices' byteLength; `claimed` replaces the fallback buffer's
/// and the index view's byteLength when not 0.
std::string meshopt_glb(size_t cut, std::uint64_t claimed) {
  std::vector<unsigned char> vertices(meshopt_encodeVertexBufferBound(4, 12));
  vertices.resize(
      meshopt_encodeVertexBuffer(vertices.data(), vertices.size(), kPositions.data(), 4, 12));
  const std::vector<unsigned int> indices32(kIndices.begin(), kIndices.end());
  std::vector<unsigned char> indices(meshopt_encodeIndexBufferBound(12, 4));
  indices.resize(meshopt_encodeIndexBuffer(indices.data(), indices.size(), indices32.data(), 12));
  std::string bin = bytes_of(vertices);
  while (bin.size() % 4 != 0)
    bin += '\0';
  const size_t index_offset = bin.size();
  bin += bytes_of(indices);
  json d = one_mesh({{"POSITION", 0}}, 1);
  d["extensionsUsed"] = {"EXT_meshopt_compression"};
  d["extensionsRequired"] = {"EXT_meshopt_compression"};
  d["accessors"] = {
      {{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
      {{"bufferView", 1}, {"componentType", 5123}, {"count", 12}, {"type", "SCALAR"}}};
  const json vertex_ext = {{"buffer", 0},      {"byteOffset", 0}, {"byteLength", vertices.size()},
                           {"byteStride", 12}, {"count", 4},      {"mode", "ATTRIBUTES"}};
  const json index_ext = {{"buffer", 0},
                          {"byteOffset", index_offset},
                          {"byteLength", indices.size() - cut},
                          {"byteStride", 2},
                          {"count", 12},
                          {"mode", "TRIANGLES"}};
  const std::uint64_t index_bytes = claimed ? claimed : 24;
  d["bufferViews"] = {{{"buffer", 1},
                       {"byteOffset", 0},
                       {"byteLength", 48},
                       {"byteStride", 12},
                       {"extensions", {{"EXT_meshopt_compression", vertex_ext}}}},
                      {{"buffer", 1},
                       {"byteOffset", 48},
                       {"byteLength", index_bytes},
                       {"extensions", {{"EXT_meshopt_compression", index_ext}}}}};
  d["buffers"] = {{{"byteLength", bin.size()}},
                  {{"byteLength", 48 + index_bytes},
                   {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}};
  return glb_bytes(d.dump(), bin);
}

TEST(GltfExtensions, MeshoptBufferViewsDecodeToTheBytesTheyEncode) {
  const fs::path dir = kDir / "meshopt";
  test::write_file(dir / "m.glb", meshopt_glb(0, 0));
  TriangleMesh mesh;
  MeshAppearance a;
  std::string error;
  ASSERT_TRUE(read_mesh(dir / "m.glb", mesh, a, error)) << error;
  ASSERT_EQ(mesh.positions.size(), 4u);
  for (size_t v = 0; v < 4; ++v)
    EXPECT_EQ(mesh.positions[v],
              glm::dvec3(kPositions[3 * v], kPositions[3 * v + 1], kPositions[3 * v + 2]));
  // meshoptimizer's index codec keeps each triangle and its winding, not its first corner.
  ASSERT_EQ(mesh.triangles.size(), 4u);
  const auto rotated = [](glm::ivec3 t) {
    while (t.x != std::min(t.x, std::min(t.y, t.z)))
      t = glm::ivec3(t.y, t.z, t.x);
    return t;
  };
  for (size_t f = 0; f < 4; ++f)
    EXPECT_EQ(rotated(mesh.triangles[f]),
              rotated(glm::ivec3(kIndices[3 * f], kIndices[3 * f + 1], kIndices[3 * f + 2])))
        << f;

  const std::string pointer = "/bufferViews/1/extensions/EXT_meshopt_compression";
  test::write_file(dir / "cut.glb", meshopt_glb(3, 0));
  EXPECT_FALSE(read_mesh(dir / "cut.glb", mesh, a, error));
  EXPECT_NE(error.find(pointer + ": meshoptimizer cannot decode"), std::string::npos) << error;
  test::write_file(dir / "claims.glb", meshopt_glb(0, 36));  // count 12 x stride 2 is 24, not 36
  EXPECT_FALSE(read_mesh(dir / "claims.glb", mesh, a, error));
  EXPECT_NE(error.find(pointer + ": count 12 x byteStride 2 is not the buffer view's byteLength "
                                 "36"),
            std::string::npos)
      << error;
  // A view claiming 2 GiB decoded is refused before anything is decoded or allocated.
  test::write_file(dir / "huge.glb", meshopt_glb(0, (std::uint64_t(2) << 30) - 48));
  EXPECT_FALSE(read_mesh(dir / "huge.glb", mesh, a, error));
  EXPECT_NE(error.find("would decode to more than 2147483648 bytes"), std::string::npos) << error;
}

/// load_scene_file of the tetrahedron with material `material` (named `name`): the first
/// object's material, the warnings; false with `error`.
bool tetrahedron_material(const json& material, Material& m, std::vector<std::string>& warnings,
                          std::string& error) {
  const fs::path dir = kDir / "materials";
  json d = tetrahedron(dir);
  d["materials"] = {material};
  d["meshes"][0]["primitives"][0]["material"] = 0;
  test::write_file(dir / "m.gltf", d.dump());
  Scene scene;
  warnings.clear();
  if (!load_scene_file((dir / "m.gltf").string(), scene, warnings, error))
    return false;
  m = scene.objects.at(0).material;
  return true;
}

/// The one warning of `warnings` (a failure when there is not exactly one).
std::string only_warning(const std::vector<std::string>& warnings) {
  EXPECT_EQ(warnings.size(), 1u);
  return warnings.empty() ? "" : warnings[0];
}

TEST(GltfMaterials, ApproximationsAreWarningsNamingTheMaterial) {
  Material m;
  std::vector<std::string> warnings;
  std::string error;
  // A smooth metal is a mirror tinted by its base colour, silently.
  ASSERT_TRUE(tetrahedron_material(json::parse(R"({"name": "chrome", "pbrMetallicRoughness":
      {"baseColorFactor": [0.9, 0.8, 0.7, 1], "metallicFactor": 1, "roughnessFactor": 0.02}})"),
                                   m, warnings, error))
      << error;
  EXPECT_EQ(m.type, MaterialType::kMirror);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  // The issue's metal of roughness 0.2 was a white diffuse surface, silently: now a mirror and
  // a warning that says what is approximated.
  ASSERT_TRUE(tetrahedron_material(json::parse(R"({"name": "brushed", "pbrMetallicRoughness":
      {"metallicFactor": 1, "roughnessFactor": 0.2}})"),
                                   m, warnings, error))
      << error;
  EXPECT_EQ(m.type, MaterialType::kMirror);
  EXPECT_NE(only_warning(warnings).find("materials[0] 'brushed': rendered as a mirror: "
                                        "roughnessFactor 0.2 rendered as a perfect mirror"),
            std::string::npos)
      << only_warning(warnings);
  // glTF's default material factors (metallic 1, roughness 1): a rough metal, diffuse.
  ASSERT_TRUE(tetrahedron_material(json::parse(R"({"name": "defaults"})"), m, warnings, error))
      << error;
  EXPECT_EQ(m.type, MaterialType::kDiffuse);
  EXPECT_NE(only_warning(warnings).find("'defaults': rendered as diffuse: metallicFactor 1 with "
                                        "roughnessFactor 1 rendered diffuse"),
            std::string::npos)
      << only_warning(warnings);
  // Transmission 0.5 was full glass, silently.
  ASSERT_TRUE(tetrahedron_material(json::parse(R"({"name": "half", "pbrMetallicRoughness":
      {"metallicFactor": 0, "roughnessFactor": 0}, "extensions": {
      "KHR_materials_transmission": {"transmissionFactor": 0.5},
      "KHR_materials_volume": {"thicknessFactor": 0.5}}})"),
                                   m, warnings, error))
      << error;
  EXPECT_EQ(m.type, MaterialType::kDielectric);
  EXPECT_NE(only_warning(warnings).find("'half': rendered as a dielectric: transmissionFactor "
                                        "0.5 rendered as full transmission"),
            std::string::npos)
      << only_warning(warnings);
  // Emission and alpha, on any kind.
  ASSERT_TRUE(tetrahedron_material(json::parse(R"({"name": "glow", "emissiveFactor": [1, 0, 0],
      "alphaMode": "BLEND", "pbrMetallicRoughness": {"metallicFactor": 0}})"),
                                   m, warnings, error))
      << error;
  EXPECT_NE(only_warning(warnings).find("emission ignored; alpha ignored (alphaMode BLEND"),
            std::string::npos)
      << only_warning(warnings);
}

TEST(GltfMaterials, TransmissiveSurfacesThatAreNoSolidsAreRefused) {
  Material m;
  std::vector<std::string> warnings;
  std::string error;
  // Without KHR_materials_volume (or with thicknessFactor 0) glTF's transmission is thin-walled.
  EXPECT_FALSE(tetrahedron_material(json::parse(R"({"name": "film", "extensions": {
      "KHR_materials_transmission": {"transmissionFactor": 1}}})"),
                                    m, warnings, error));
  EXPECT_NE(error.find("m.gltf: materials[0] 'film': KHR_materials_transmission without "
                       "KHR_materials_volume thicknessFactor > 0 is a thin-walled surface"),
            std::string::npos)
      << error;
  // A flat open quad declared a volume encloses none: refused as a JSON scene's dielectric quad.
  const fs::path dir = kDir / "quad";
  const std::vector<float> quad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<std::uint16_t> indices = {0, 1, 2, 0, 2, 3};
  test::write_file(dir / "quad.bin", bytes_of(quad) + bytes_of(indices));
  json d = one_mesh({{"POSITION", 0}}, 1);
  d["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                    {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}};
  d["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                      {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}}};
  d["buffers"] = {{{"uri", "quad.bin"}, {"byteLength", 60}}};
  d["materials"] = {json::parse(R"({"pbrMetallicRoughness": {"roughnessFactor": 0,
      "metallicFactor": 0}, "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_volume": {"thicknessFactor": 1}}})")};
  d["meshes"][0]["primitives"][0]["material"] = 0;
  test::write_file(dir / "quad.gltf", d.dump());
  Scene scene;
  EXPECT_FALSE(load_scene_file((dir / "quad.gltf").string(), scene, warnings, error));
  EXPECT_NE(error.find("quad.gltf: meshes[0]: a transmissive surface that encloses no volume"),
            std::string::npos)
      << error;
  // The closed tetrahedron with the same material is glass.
  EXPECT_TRUE(tetrahedron_material(d["materials"][0], m, warnings, error)) << error;
  EXPECT_EQ(m.type, MaterialType::kDielectric);
}

}  // namespace
}  // namespace gfield
