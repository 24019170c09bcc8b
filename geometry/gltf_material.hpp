#pragma once
// A glTF material as a gfield material (docs/scenes.md, "glTF features"): what gfield renders
// exactly, what it approximates (each approximation a warning that names the material), and what
// it refuses. Internal to the glTF code (gltf_scene.cpp).
//
//  - KHR_materials_transmission > 0 with KHR_materials_volume thicknessFactor > 0: a dielectric
//    solid, KHR_materials_ior (default 1.5) and absorption -ln(attenuationColor) /
//    attenuationDistance. Approximated: a transmissionFactor below 1 (full transmission), a
//    roughnessFactor above 0.05 (smooth), a base colour other than white (no tint), transmission
//    textures (ignored). Refused: transmission without a volume (thin-walled, the glTF default),
//    which gfield's closed dielectrics cannot render; a JSON scene refuses a dielectric quad so.
//  - metallicFactor >= 0.5 with roughnessFactor <= 0.5: a mirror tinted by baseColorFactor.
//    Approximated: metallic below 1, roughness above 0.05 (a perfect mirror), a baseColorTexture
//    (the factor alone tints).
//  - otherwise: diffuse with the mesh's own base colour (factor x texture x COLOR_0).
//    Approximated: metallic above 0 (a rough metal or a partly metallic surface as diffuse).
//  - every kind: emission, normal and occlusion textures, alpha (BLEND, MASK, a base colour alpha
//    below 1) and a base colour texture's sampler that does not repeat or is not linear are
//    approximated (ignored, opaque, repeating bilinear).

#include <string>
#include <vector>

#include "gfield/scene.hpp"

namespace gfield {

struct GltfDocument;

/// The gfield material of material `index` of `d` (-1: glTF's default material, white diffuse).
/// `warnings` gets one line "FILE: materials[I] 'NAME': rendered as KIND: approximation; ..."
/// when gfield approximates it. False with `error` "FILE: materials[I] 'NAME': problem" for a
/// value out of range (transmission [0, 1], ior [1e-6, 1e6] as in JSON scenes, attenuation
/// distance, thickness >= 0) or a thin-walled transmissive material.
bool gltf_object_material(const GltfDocument& d, int index, Material& material,
                          std::vector<std::string>& warnings, std::string& error);

}  // namespace gfield
