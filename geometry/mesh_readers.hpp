#pragma once
// The mesh file readers behind load_mesh (mesh_io.hpp), one per format, each parsing a whole file
// held in memory. Every count read from a header is checked against the limits (gfield/limits.hpp)
// and against the bytes left before anything is allocated or looped over; every coordinate
// against kMaxCoordinate; every index against the vertex count. A file that ends early is an
// error, never a mesh with fewer faces.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"

namespace gfield {

/// What a reader builds: the triangles as read (polygons fan-triangulated), its counts, and the
/// surface attributes of the file (all optional; mesh_io.cpp turns them into a MeshAppearance).
struct MeshSoup {
  TriangleMesh mesh;
  MeshLoadStats stats;
  std::vector<glm::vec2> uvs;                ///< texture coordinates (OBJ vt; PLY: one per vertex)
  std::vector<std::int32_t> corner_uvs;      ///< 3F indices into uvs (-1: none); empty: no uvs
  std::vector<glm::vec3> vertex_color;       ///< V linear RGB (white where a vertex gave none)
  std::vector<int> face_material;            ///< F indices into materials (-1: none); empty: none
  std::vector<BaseColorMaterial> materials;  ///< OBJ: one per usemtl name, filled by its library
  std::vector<std::string> libraries;        ///< OBJ mtllib files as written
  std::vector<std::string> texture_files;    ///< PLY "comment TextureFile NAME" as written
};

/// The texture coordinates and material of one polygon (uvs: one index into MeshSoup::uvs per
/// corner, or empty).
struct PolygonAttributes {
  std::span<const std::int64_t> uvs;
  int material = -1;
};

/// Where reading stopped: the 1-based line of a text file (0 for binary data or the whole file)
/// and what is wrong (JSON documents say where by a pointer: JsonFailure, gfield/located_json.hpp).
struct ReadFailure {
  size_t line = 0;
  std::string what;
};

/// Appends a vertex (rounded to float, as every format's coordinates are read); false with `what`
/// when a coordinate is not finite or beyond kMaxCoordinate.
bool add_vertex(MeshSoup& soup, double x, double y, double z, std::string& what);
/// Appends a polygon of 0-based `corners` (each already checked against the vertex count),
/// fan-triangulated; false with `what` for fewer than 3 or more than kMaxPolygonCorners corners,
/// or more than kMaxMeshTriangles triangles in all.
bool add_polygon(MeshSoup& soup, std::span<const std::int64_t> corners, std::string& what,
                 const PolygonAttributes& attributes = {});
/// Appends a texture coordinate; false with `what` when it is not finite or beyond
/// kMaxTextureCoordinate.
bool add_uv(MeshSoup& soup, double u, double v, std::string& what);
/// Sets the colour of the last vertex added (linear RGB); false with `what` when a component is
/// not finite or outside [0, kMaxColorComponent]. Earlier vertices without one become white.
bool set_vertex_color(MeshSoup& soup, glm::dvec3 color, std::string& what);
/// True when 0 <= index < vertices; else false with `what` naming the index.
bool check_index(std::int64_t index, std::int64_t vertices, std::string& what);
/// "header claims COUNT WHAT, more than the BYTES bytes left can hold" when count * min_bytes
/// exceeds `bytes` (or count exceeds `limit`); true when it fits.
bool check_count(std::int64_t count, std::int64_t limit, std::uint64_t min_bytes,
                 std::uint64_t bytes, std::string_view what_counted, std::string& what);

bool read_obj(std::string_view data, MeshSoup& soup, ReadFailure& failure);
/// Reads the material libraries soup.libraries of OBJ file `obj` (relative to its folder) and
/// gives soup.materials their Kd and map_Kd (soup.texture_files). A missing library and a
/// material no library defines are warnings (white materials); a malformed library is an error
/// "OBJ: material library FILE:LINE: problem", and so is a library or map outside the OBJ file's
/// folder unless `outside` is kAllowed (confined_path.hpp).
bool read_material_libraries(const std::string& obj, OutsidePaths outside, MeshSoup& soup,
                             std::vector<std::string>& warnings, std::string& error);
bool read_off(std::string_view data, MeshSoup& soup, ReadFailure& failure);
bool read_ply(std::string_view data, MeshSoup& soup, ReadFailure& failure);
bool read_stl(std::string_view data, MeshSoup& soup, ReadFailure& failure);

}  // namespace gfield
