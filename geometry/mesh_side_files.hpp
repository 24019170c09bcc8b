#pragma once
// The files a mesh file names beside itself, read when it is loaded with its appearance: an OBJ's
// material libraries and the texture maps they name, a PLY's "comment TextureFile" texture (a
// glTF file's buffers and images: gltf_external_files, gltf_mesh.hpp). Paths as the working
// folder reaches them; files that do not exist are listed too (their appearance changes what
// the mesh looks like); files outside the mesh's folder only when `outside` is kAllowed
// (confined_path.hpp).

#include <string>
#include <vector>

#include "gfield/confined_path.hpp"

namespace gfield {

/// An OBJ file's mtllib files and the maps (map_Kd, bump, ...) they name.
std::vector<std::string> obj_side_files(const std::string& obj, OutsidePaths outside);

/// A PLY file's "comment TextureFile NAME" files (header lines).
std::vector<std::string> ply_side_files(const std::string& ply, OutsidePaths outside);

}  // namespace gfield
