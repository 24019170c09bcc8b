#pragma once
// Triangle meshes read from OBJ, PLY, OFF and STL files through OpenMesh's readers.
// Polygons are fan-triangulated; the soup is kept as read (no welding, no repair), so that the
// topology report describes the file itself.

#include <string>
#include <vector>

#include <glm/glm.hpp>

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

/// Reads `filename` (.obj, .ply, .off, .stl; case-insensitive extension). False with an error
/// "FILE: problem" for a missing/unreadable/empty file, an unknown extension, a file with 0
/// faces, non-finite coordinates or face indices out of range.
bool load_mesh(const std::string& filename, TriangleMesh& mesh, std::string& error,
               MeshLoadStats* stats = nullptr);

/// Writes an OBJ file (atomically). For debugging and for generated test meshes.
bool save_obj(const std::string& filename, const TriangleMesh& mesh, std::string& error);

}  // namespace gfield
