#pragma once
// Triangle meshes read from OBJ, PLY (ASCII and binary), OFF and STL (ASCII and binary) files by
// the project's own readers (mesh_readers.hpp), and from glTF 2.0 files (.gltf, .glb:
// gltf_mesh.hpp), which check every count, index and coordinate against the file and the limits
// of gfield/limits.hpp before trusting it. Polygons are fan-triangulated; the soup is kept as
// read (no welding, no repair; STL corners at identical positions become one vertex), so that
// the topology report describes the file itself. Coordinates are read as 32-bit floats. Besides
// the triangles a mesh may carry texture coordinates, vertex colours and materials
// (mesh_appearance.hpp).

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/confined_path.hpp"

namespace gfield {

/// An indexed triangle mesh. Positions in mesh (file) coordinates; triangles index positions,
/// in the file's winding order.
struct TriangleMesh {
  std::vector<glm::dvec3> positions;  ///< V points
  std::vector<glm::ivec3> triangles;  ///< F triangles, indices in [0, V)
};

/// What the loader saw besides the triangles.
struct MeshLoadStats {
  size_t polygons = 0;      ///< faces in the file
  size_t triangulated = 0;  ///< of those, polygons with more than 3 corners (fan-triangulated)
};

struct MeshAppearance;

/// A mesh to read: a file and, for a glTF file, which of its meshes; how to read what it names.
struct MeshSource {
  std::string file;
  /// glTF: a mesh's name, or its index when no mesh has that name; "" reads every primitive of
  /// the file's scene, placed by its nodes, as one mesh. Other formats: "" only.
  std::string part;
  /// The files the mesh names (glTF buffers and images, OBJ material libraries and their maps, a
  /// PLY's texture) must lie in the mesh file's folder unless kAllowed (confined_path.hpp).
  OutsidePaths outside_paths = OutsidePaths::kRefused;
  /// false: textures are read to their headers (MeshTexture::image gets the width and height
  /// they claim, no pixels): for commands that need no pixels (`gfield info`).
  bool texture_pixels = true;
};

/// Reads `filename` (.obj, .ply, .off, .stl, .gltf, .glb: mesh_formats.hpp; any case). False
/// with a one-line error "FILE[:LINE]: problem" for a missing/unreadable/empty file or one above
/// kMaxMeshFileBytes, an unknown extension, a malformed or truncated file, a header whose counts
/// the file cannot hold, a face with fewer than 3 or more than kMaxPolygonCorners corners, a file
/// with 0 faces, a coordinate that is not finite or beyond kMaxCoordinate (1e15), face indices
/// out of range, texture coordinates that are not finite or beyond kMaxTextureCoordinate, colours
/// outside [0, kMaxColorComponent] (glTF: gltf_mesh.hpp).
bool load_mesh(const std::string& filename, TriangleMesh& mesh, std::string& error,
               MeshLoadStats* stats = nullptr);

/// The same for `source`, with the surface's attributes into `appearance` when it is not null
/// (textures decoded: a missing texture or material library adds a warning and gives mid-grey or
/// white; a texture that is no image is an error "MESH: texture FILE: problem").
bool load_mesh(const MeshSource& source, TriangleMesh& mesh, MeshAppearance* appearance,
               std::vector<std::string>& warnings, std::string& error,
               MeshLoadStats* stats = nullptr);

/// True for the extensions of glTF files (.gltf, .glb, any case).
bool is_gltf_file(const std::string& filename);

}  // namespace gfield
