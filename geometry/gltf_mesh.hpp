#pragma once
// Meshes of glTF 2.0 files (.gltf, .glb) as gfield meshes: a primitive's POSITION and indices
// (modes TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN), the TEXCOORD_n set its material's
// baseColorTexture reads (texCoord, KHR_texture_transform's texCoord, offset, rotation and scale
// applied; v flipped to gfield's v up), COLOR_0 (linear) and its material's baseColorFactor and
// baseColorTexture (decoded by gfield: mesh_appearance.hpp). Quantised attributes
// (KHR_mesh_quantization: normalised or integer bytes and shorts) read as the specification
// says; compressed files (Draco, meshopt) are decoded first (gltf_decompress.hpp). The whole
// file reads as every primitive of its scene placed by its nodes; one mesh (MeshSource::part:
// its name, or "#INDEX") as its primitives in the mesh's own coordinates. Checks: those of
// load_gltf_document (gltf_document.hpp), then a primitive mode other than the three, a missing
// POSITION, sparse accessors, accessor types or component types that do not fit their attribute
// (glTF 2.0's table, widened by KHR_mesh_quantization when the file uses it), indices beyond
// POSITION, coordinates beyond kMaxCoordinate, texture coordinates beyond kMaxTextureCoordinate
// (after the transform), colours outside [0, kMaxColorComponent]: one line
// "FILE: meshes[M].primitives[P]: problem".

#include <string>
#include <vector>

#include "geometry/mesh_io.hpp"

namespace gfield {

/// load_mesh for glTF files (mesh_io.hpp).
bool load_gltf_mesh(const MeshSource& source, TriangleMesh& mesh, MeshAppearance* appearance,
                    std::vector<std::string>& warnings, std::string& error,
                    MeshLoadStats* stats = nullptr);

struct GltfDocument;

/// load_gltf_mesh of a document already read (gltf_document.hpp): mesh `part` ("" the whole
/// scene), textures decoded when `texture_pixels`, no appearance when `appearance` is null.
bool read_gltf_mesh(const GltfDocument& d, const std::string& part, TriangleMesh& mesh,
                    MeshAppearance* appearance, bool texture_pixels,
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
