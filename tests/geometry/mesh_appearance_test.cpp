// Mesh attributes: OBJ vt, vertex colours, mtllib/usemtl with Kd
// and map_Kd; PLY u v and red green blue; faces without uv; the base colour at a point against
// colours worked out by hand from the files (sRGB decoded: (v + 0.055)^2.4 / 1.055^2.4).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/image.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(gfield::build_paths::test_tmp()) / "mesh_appearance";

std::string write_file(const std::string& name, const std::string& contents) {
  fs::create_directories(kDir);
  const fs::path path = kDir / name;
  std::ofstream(path, std::ios::binary) << contents;
  return path.string();
}

/// sRGB to linear, written out (IEC 61966-2-1).
double linear(double srgb) {
  return srgb <= 0.04045 ? srgb / 12.92 : std::pow((srgb + 0.055) / 1.055, 2.4);
}

struct Loaded {
  TriangleMesh mesh;
  MeshAppearance appearance;
  std::vector<std::string> warnings;
};

Loaded load(const std::string& file) {
  Loaded l;
  std::string error;
  EXPECT_TRUE(load_mesh(MeshSource{file, ""}, l.mesh, &l.appearance, l.warnings, error)) << error;
  return l;
}

void expect_color(glm::vec3 got, glm::dvec3 want, double tolerance) {
  EXPECT_NEAR(got.r, want.r, tolerance);
  EXPECT_NEAR(got.g, want.g, tolerance);
  EXPECT_NEAR(got.b, want.b, tolerance);
}

TEST(MeshAppearance, ObjTextureCoordinatesMaterialsAndTextures) {
  // A 2 x 1 texture: left texel red (sRGB 255, 0, 0), right texel sRGB (0, 128, 255).
  Image texture(2, 1);
  texture.pixels[0] = glm::vec3(1.0f, 0.0f, 0.0f);
  texture.pixels[1] = glm::vec3(0.0f, float(linear(128.0 / 255.0)), 1.0f);
  std::string error;
  fs::create_directories(kDir);
  ASSERT_TRUE(save_image((kDir / "two.png").string(), texture, error)) << error;
  write_file("quad.mtl",
             "newmtl painted\nKd 0.5 1 1\nmap_Kd two.png\nnewmtl plain\nKd 0.2 0.4 0.6\n");
  // Faces 1 and 2 (the first face's uv and material must be kept) sample the texture's two
  // texel centres; faces 3 and 4 have no uv and the plain material.
  const std::string obj =
      write_file("quad.obj",
                 "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0.25 0.5\nvt 0.75 0.5\n"
                 "usemtl painted\nf 1/1 2/1 3/1\nf 1/2 3/2 4/2\nusemtl plain\nf 1 2 4\nf 2 3 4\n");
  const Loaded l = load(obj);
  EXPECT_TRUE(l.warnings.empty());
  ASSERT_EQ(l.mesh.triangles.size(), 4u);
  ASSERT_EQ(l.appearance.corner_uv.size(), 12u);
  EXPECT_EQ(l.appearance.corner_uv[0], glm::vec2(0.25f, 0.5f));  // the first face's uv
  EXPECT_EQ(l.appearance.corner_uv[6], glm::vec2(0.0f));         // faces without uv: (0, 0)
  ASSERT_EQ(l.appearance.face_material.size(), 4u);
  EXPECT_EQ(l.appearance.face_material[0], l.appearance.face_material[1]);
  EXPECT_NE(l.appearance.face_material[0], l.appearance.face_material[2]);
  ASSERT_EQ(l.appearance.textures.size(), 1u);
  EXPECT_TRUE(carries_base_color(l.appearance));
  const glm::dvec3 centre(1.0 / 3.0);
  // uv (0.25, 0.5) is the left texel's centre: Kd x red; (0.75, 0.5) the right one's.
  expect_color(base_color_at(l.mesh, l.appearance, 0, centre), {0.5, 0.0, 0.0}, 1e-4);
  expect_color(base_color_at(l.mesh, l.appearance, 1, centre), {0.0, linear(128.0 / 255.0), 1.0},
               1e-4);
  expect_color(base_color_at(l.mesh, l.appearance, 2, centre), {0.2, 0.4, 0.6}, 1e-6);
  expect_color(base_color_at(l.mesh, l.appearance, 3, centre), {0.2, 0.4, 0.6}, 1e-6);
  // Halfway between the texel centres (u = 0.5): the bilinear mean.
  expect_color(texture_lookup(l.appearance.textures[0].image, {0.5f, 0.5f}),
               {0.5, 0.5 * linear(128.0 / 255.0), 0.5}, 1e-4);
}

TEST(MeshAppearance, PlyTextureCoordinatesAndVertexColours) {
  const std::string ply =
      write_file("tri.ply",
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                 "property float z\nproperty float s\nproperty float t\nproperty uchar red\n"
                 "property uchar green\nproperty uchar blue\nelement face 1\n"
                 "property list uchar int vertex_indices\nend_header\n"
                 "0 0 0 0 0 255 0 0\n1 0 0 1 0 0 255 0\n0 1 0 0 1 0 0 255\n3 0 1 2\n");
  const Loaded l = load(ply);
  ASSERT_EQ(l.appearance.corner_uv.size(), 3u);
  EXPECT_EQ(l.appearance.corner_uv[1], glm::vec2(1.0f, 0.0f));
  ASSERT_EQ(l.appearance.vertex_color.size(), 3u);
  EXPECT_TRUE(carries_base_color(l.appearance));
  expect_color(base_color_at(l.mesh, l.appearance, 0, {0.5, 0.25, 0.25}), {0.5, 0.25, 0.25}, 1e-6);
}

TEST(MeshAppearance, ObjVertexColoursAreSrgbInTheUnitRangeAndLinearAbove) {
  const std::string obj =
      write_file("colours.obj", "v 0 0 0 0.5 0.5 0.5\nv 1 0 0 2 1 0.5\nv 0 1 0\nf 1 2 3\n");
  const Loaded l = load(obj);
  ASSERT_EQ(l.appearance.vertex_color.size(), 3u);
  expect_color(l.appearance.vertex_color[0], glm::dvec3(linear(0.5)), 1e-6);
  expect_color(l.appearance.vertex_color[1], {2.0, 1.0, 0.5}, 1e-6);
  expect_color(l.appearance.vertex_color[2], {1.0, 1.0, 1.0}, 0.0);  // none given: white
}

TEST(MeshAppearance, PlainMeshCarriesNoBaseColour) {
  const Loaded l = load(std::string(gfield::build_paths::mesh_dir()) + "/torus.obj");
  EXPECT_FALSE(carries_base_color(l.appearance));
  EXPECT_TRUE(l.appearance.textures.empty());
}

}  // namespace
}  // namespace gfield
