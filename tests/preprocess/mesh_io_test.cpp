#include "geometry/mesh_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "preprocess/topology.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

std::string write_temp(const std::string& name, const std::string& contents) {
  const std::string path =
      (fs::path(gfield::build_paths::test_tmp()) / ("mesh_io_" + name)).string();
  std::ofstream(path, std::ios::binary) << contents;
  return path;
}

std::string load_error(const std::string& path) {
  TriangleMesh mesh;
  std::string error;
  EXPECT_FALSE(load_mesh(path, mesh, error)) << path;
  EXPECT_EQ(error.rfind(path, 0), 0u) << "error must start with the file name: " << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
  return error;
}

const char* kTetrahedronObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";

TEST(MeshIo, ReadsAllFourFormatsOfOneTetrahedron) {
  const std::string off =
      "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  const std::string stl =
      "solid t\n"
      "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\n"
      "endfacet\n"
      "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\n"
      "endfacet\n"
      "facet normal 1 1 1\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\n"
      "endfacet\n"
      "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\n"
      "endfacet\nendsolid t\n";
  for (const auto& [name, contents] :
       {std::pair{"tet.obj", std::string(kTetrahedronObj)}, std::pair{"tet.off", off},
        std::pair{"tet.ply", ply}, std::pair{"tet.STL", stl}}) {
    TriangleMesh mesh;
    std::string error;
    ASSERT_TRUE(load_mesh(write_temp(name, contents), mesh, error)) << name << ": " << error;
    EXPECT_EQ(mesh.triangles.size(), 4u) << name;
    const TopologyReport r = analyze_topology(mesh);
    ASSERT_EQ(r.components.size(), 1u) << name;
    EXPECT_EQ(r.components[0].euler_characteristic, 2) << name;
    EXPECT_EQ(r.components[0].genus, 0) << name;
    EXPECT_TRUE(r.closed()) << name;
    EXPECT_TRUE(r.components[0].oriented) << name;
    EXPECT_NEAR(r.area, 1.5 + std::sqrt(3.0) / 2.0, 1e-6) << name;
  }
}

TEST(MeshIo, TriangulatesPolygons) {
  // A cube of 6 quads -> 12 triangles, closed, genus 0.
  const std::string cube =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  TriangleMesh mesh;
  MeshLoadStats stats;
  std::string error;
  ASSERT_TRUE(load_mesh(write_temp("cube.obj", cube), mesh, error, &stats)) << error;
  EXPECT_EQ(stats.polygons, 6u);
  EXPECT_EQ(stats.triangulated, 6u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  const TopologyReport r = analyze_topology(mesh);
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_EQ(r.components[0].genus, 0);
  EXPECT_TRUE(r.closed());
}

TEST(MeshIo, BadInputGivesOneLineErrors) {
  EXPECT_NE(load_error(write_temp("missing-dir/none.obj", "")).find("no such file"),
            std::string::npos);
  EXPECT_NE(load_error(write_temp("empty.obj", "")).find("empty file"), std::string::npos);
  EXPECT_NE(load_error(write_temp("mesh.xyz", kTetrahedronObj)).find("unknown mesh extension"),
            std::string::npos);
  EXPECT_NE(load_error(write_temp("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")).find("no faces"),
            std::string::npos);
  EXPECT_NE(load_error(write_temp("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"))
                .find("out of range"),
            std::string::npos);
  EXPECT_NE(load_error(write_temp("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n"))
                .find("out of range"),
            std::string::npos);
  EXPECT_NE(load_error(write_temp("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"))
                .find("NaN or infinite"),
            std::string::npos);
  EXPECT_NE(load_error(write_temp("inf.off", "OFF\n3 1 0\n0 0 0\ninf 0 0\n0 1 0\n3 0 1 2\n"))
                .find("NaN or infinite"),
            std::string::npos);
  EXPECT_NE(load_error(write_temp("huge.off", "OFF\n3 1 0\n0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n"))
                .find("beyond the limit of 1e15"),
            std::string::npos);
  // Binary PLY holding triangle strips: parses, but has no faces.
  std::string strips =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement tristrips 1\n"
      "property list int int vertex_indices\nend_header\n";
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  strips.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const int strip[4] = {3, 0, 1, 2};
  strips.append(reinterpret_cast<const char*>(strip), sizeof strip);
  EXPECT_NE(load_error(write_temp("strips.ply", strips)).find("no faces"), std::string::npos);
  fs::create_directories(fs::path(gfield::build_paths::test_tmp()) / "mesh_io_dir.obj");
  load_error((fs::path(gfield::build_paths::test_tmp()) / "mesh_io_dir.obj").string());
}

}  // namespace
}  // namespace gfield
