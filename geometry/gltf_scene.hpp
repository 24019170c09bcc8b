#pragma once
// glTF 2.0 files as gfield scenes (docs/scenes.md, "glTF scenes"): every node of the file's scene
// that holds a mesh becomes a mesh object (instances of one glTF mesh share its asset), placed by
// its world matrix (translation, rotation, positive scale; a shear is dropped with a warning, a
// mirroring matrix refused); the first camera node is the camera (none, or an orthographic one:
// a camera fitted to the scene's bounds); KHR_lights_punctual directional and point lights (spot
// lights become point lights, with a warning); the material of a mesh's first primitive decides
// the object's: KHR_materials_transmission -> dielectric (KHR_materials_ior, KHR_materials_volume
// attenuation as absorption), metallic 1 with roughness <= 0.05 -> mirror tinted by the base
// colour, otherwise diffuse with the mesh's own base colour (factor x texture, per primitive).
// The image size, environment, ambient light and purpose come from the scene's (or the asset's)
// extras "gfield" object, as in a JSON scene; without it: 512 x 512 (the camera's aspect ratio),
// the studio, ambient 0.1 (1 when the file has no light).

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/scene.hpp"

namespace gfield {

/// Reads glTF file `filename` as a scene, its URIs confined to its folder unless `outside` is
/// kAllowed (confined_path.hpp). Each mesh's assets are looked for beside the file as
/// MeshAsset::asset (use_asset_folder points elsewhere). Bounds (the fitted camera's) come from
/// the POSITION data; declared min and max that the data contradict are warnings. False with
/// "FILE: problem".
bool load_gltf_scene(const std::string& filename, OutsidePaths outside, Scene& scene,
                     std::vector<std::string>& warnings, std::string& error);

/// Appends the mesh objects of glTF file `filename` (and their meshes) to `scene`, each placed by
/// `placement` after its node's world matrix: a JSON scene's `"shape": "gltf"` object. Lights
/// and cameras of the file are not used.
bool append_gltf_objects(const std::string& filename, OutsidePaths outside,
                         const glm::dmat4& placement, Scene& scene,
                         std::vector<std::string>& warnings, std::string& error);

/// The asset name of mesh `index` named `name` of glTF file `filename`: "STEM.INDEX-NAME" (the
/// name reduced to letters, digits, '-' and '_', at most 40 of them; "STEM.INDEX" without one).
std::string gltf_asset_name(const std::string& filename, int index, const std::string& name);

}  // namespace gfield
