#pragma once
// A gfield scene written as a binary glTF 2.0 file (`gfield export-gltf`), so that the JSON
// example scenes have a glTF twin the project makes itself. What it writes is what gfield's glTF
// reader maps back (gltf_scene.hpp): one node per object with its translation, rotation and
// scale; mesh objects as the mesh file's triangles with their texture coordinates, vertex
// colours and, per material of the file, a primitive whose baseColorFactor is the object's colour
// times the material's and whose baseColorTexture is the material's texture (PNG); a quad as two
// triangles with its procedural texture baked into a 1024 x 1024 PNG; diffuse -> base colour,
// mirror -> metallic 1, roughness 0 and the tint as base colour, dielectric ->
// KHR_materials_transmission, KHR_materials_ior and KHR_materials_volume (absorption as
// attenuation over 1 unit); the camera as the first node; lights as KHR_lights_punctual; the image
// size, environment, ambient light and purpose in the scene's extras "gfield".

#include <string>

#include "gfield/scene.hpp"

namespace gfield {

/// Writes `scene` to `filename` (.glb) atomically. False with "FILE: problem" for a shape other
/// than a mesh or a quad, a mesh that does not read, a colour above 1 (glTF's base colour ends
/// at 1) or a failed write.
bool write_gltf_scene(const Scene& scene, const std::string& filename, std::string& error);

}  // namespace gfield
