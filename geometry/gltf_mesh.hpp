#pragma once
// Meshes of glTF 2.0 files (.gltf, .glb) as gfield meshes: a primitive's POSITION and indices
// (modes TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN), TEXCOORD_0 (v flipped to gfield's v up),
// COLOR_0 (linear) and its material's baseColorFactor and baseColorTexture (decoded by gfield:
// mesh_appearance.hpp). The whole file reads as every primitive of its scene placed by its nodes;
// one mesh (MeshSource::part: its name, or "#INDEX") as its primitives in the mesh's own
// coordinates. Checks: those of load_gltf_document (gltf_document.hpp), then a primitive mode
// other than the three, a missing POSITION, sparse accessors, accessor types that do not fit
// their attribute, indices beyond POSITION, coordinates beyond kMaxCoordinate, texture
// coordinates beyond kMaxTextureCoordinate, colours outside [0, kMaxColorComponent]: one line
// "FILE: meshes[M].primitives[P]: problem".

#include <string>
#include <vector>

#include "geometry/mesh_io.hpp"

namespace gfield {

/// load_mesh for glTF files (mesh_io.hpp).
bool load_gltf_mesh(const MeshSource& source, TriangleMesh& mesh, MeshAppearance* appearance,
                    std::vector<std::string>& warnings, std::string& error,
                    MeshLoadStats* stats = nullptr);

/// MeshSource::part of mesh `index` of a glTF file: "#INDEX".
std::string gltf_mesh_part(int index);

/// The files glTF file `filename` names (external buffers and images, relative to its folder;
/// those outside it only when `outside` is kAllowed): what its build id hashes besides the file
/// (preprocess/build_inputs.hpp). Empty when the file cannot be read or parsed (its build then
/// fails with the reason).
std::vector<std::string> gltf_external_files(const std::string& filename, OutsidePaths outside);

}  // namespace gfield
