#pragma once
// A gfield scene written as a binary glTF 2.0 file (`gfield export-gltf`), so that every example
// scene has a glTF twin the project makes itself. What it writes is what gfield's glTF reader
// maps back (gltf_scene.hpp): one node per object with its translation, rotation and scale; its
// mesh and material as gltf_export_objects.hpp writes them (mesh files with their texture
// coordinates, colours and textures; quads; analytic shapes tessellated with GltfExportOptions's
// segments; procedural textures baked; dielectrics with KHR_materials_transmission, _ior and
// _volume on materials that are not double-sided); the camera as the first node; lights as
// KHR_lights_punctual; the image size, environment, ambient light and purpose in the scene's
// extras "gfield".

#include <string>

#include "gfield/scene.hpp"

namespace gfield {

struct GltfExportOptions {
  /// Segments around the Y axis of spheres (segments / 2 rings), cylinders and hollow cylinders.
  int segments = 128;
};

/// Writes `scene` to `filename` (.glb) atomically. False with "SCENE: objects[I] 'NAME': problem"
/// (SCENE: scene.filename) for a mesh that does not read, a colour above 1 (glTF's base colour
/// ends at 1), a texture that does not encode; segments outside [kMinShapeSegments,
/// kMaxShapeSegments] (shape_tessellation.hpp), a failed write: "FILE: problem".
bool write_gltf_scene(const Scene& scene, const std::string& filename,
                      const GltfExportOptions& options, std::string& error);

}  // namespace gfield
