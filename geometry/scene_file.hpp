#pragma once
// Scene files as the tools read them: a JSON scene (docs/scenes.md, core's parser) with its glTF
// objects (`"shape": "gltf"`) expanded into mesh objects, or a glTF file (gltf_scene.hpp); then
// every diffuse mesh object that did not name a "texture" takes its mesh's own base colour when
// the mesh carries one (texture, vertex or material colours: TextureType::kMesh), and a "mesh"
// texture without a "color" gets colour 1; dielectrics whose bounding boxes intersect are a
// warning (they must not overlap). `gfield render` and `gfield-view` read scenes here.

#include <string>
#include <vector>

#include "gfield/scene.hpp"

namespace gfield {

/// Reads `filename` (.json, .gltf, .glb); the files it names, and those its meshes name, are
/// confined as confined_path.hpp says unless `outside` is kAllowed. `warnings` receives what the
/// tools print and go on with (a missing texture or material library, a glTF transform that
/// shears, a glTF accessor's false bounds, dielectrics whose boxes intersect, ...). False with a
/// one-line error (JSON: "FILE:LINE:COLUMN: path: problem"; a glTF object of a JSON scene:
/// "SCENE:LINE:COLUMN: objects[I]: GLTF: problem").
bool load_scene_file(const std::string& filename, Scene& scene, std::vector<std::string>& warnings,
                     std::string& error, OutsidePaths outside = OutsidePaths::kRefused);

/// Sets the texture and colour defaults of the diffuse mesh objects of `scene` from their meshes
/// (read here; see above). False with the first mesh's error.
bool resolve_mesh_materials(Scene& scene, std::vector<std::string>& warnings, std::string& error);

}  // namespace gfield
