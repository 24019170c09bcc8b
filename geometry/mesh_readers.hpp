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

#include "geometry/mesh_io.hpp"

namespace gfield {

/// What a reader builds: the triangles as read (polygons fan-triangulated) and its counts.
struct MeshSoup {
  TriangleMesh mesh;
  MeshLoadStats stats;
};

/// Where reading stopped: the 1-based line of a text file (0 for binary data or the whole file)
/// and what is wrong.
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
bool add_polygon(MeshSoup& soup, std::span<const std::int64_t> corners, std::string& what);
/// True when 0 <= index < vertices; else false with `what` naming the index.
bool check_index(std::int64_t index, std::int64_t vertices, std::string& what);
/// "header claims COUNT WHAT, more than the BYTES bytes left can hold" when count * min_bytes
/// exceeds `bytes` (or count exceeds `limit`); true when it fits.
bool check_count(std::int64_t count, std::int64_t limit, std::uint64_t min_bytes,
                 std::uint64_t bytes, std::string_view what_counted, std::string& what);

bool read_obj(std::string_view data, MeshSoup& soup, ReadFailure& failure);
bool read_off(std::string_view data, MeshSoup& soup, ReadFailure& failure);
bool read_ply(std::string_view data, MeshSoup& soup, ReadFailure& failure);
bool read_stl(std::string_view data, MeshSoup& soup, ReadFailure& failure);

}  // namespace gfield
