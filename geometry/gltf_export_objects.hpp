#pragma once
// Scene objects as the glTF meshes and materials of `gfield export-gltf` (gltf_writer.hpp):
// mesh files with their texture coordinates, vertex colours and textures (one primitive per
// material of the file; a mesh of flat normals with a vertex per face corner, so that it reads
// back flat); quads as two triangles; spheres, boxes, cylinders, slabs and hollow cylinders
// tessellated (shape_tessellation.hpp); procedural textures baked into a 1024 x 1024 PNG. The
// materials: diffuse -> base colour; mirror -> metallic 1, roughness 0, the tint as base colour;
// dielectric -> KHR_materials_transmission 1, KHR_materials_ior, KHR_materials_volume
// (thicknessFactor: the smallest side of the object's box in its own coordinates; absorption as
// attenuationColor over attenuationDistance 1) on a material that is not doubleSided (a closed
// solid: the volume's boundary). Internal to the glTF writer.

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/glb_builder.hpp"
#include "gfield/scene.hpp"

namespace gfield {

/// What the objects of a scene became, so that instances share them: per mesh asset and layout
/// its vertex accessors, per texture its glTF texture, per object geometry and material the mesh.
struct GltfExportCache {
  std::map<std::string, nlohmann::json> attributes;
  std::map<std::string, int> textures;
  std::map<std::string, int> meshes;
};

/// Appends the glTF mesh of object `o` of `scene` to `b` (or finds it in `cache`): its index in
/// `mesh_index`. Round shapes get `segments` segments around. False with `error` (without the
/// object's place) for a mesh file that does not read, a texture that does not encode, a base
/// colour above 1 (glTF's baseColorFactor ends at 1).
bool export_object_mesh(GlbBuilder& b, const Scene& scene, const SceneObject& o, int segments,
                        GltfExportCache& cache, int& mesh_index, std::string& error);

}  // namespace gfield
