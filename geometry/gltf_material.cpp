#include "geometry/gltf_material.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/gltf_document.hpp"
#include "gfield/limits.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

using nlohmann::json;

/// The factors of a glTF material that decide gfield's mapping.
struct GltfFactors {
  double transmission = 0.0, ior = 1.5, distance = 1e300, thickness = 0.0;
  double metallic = 1.0, roughness = 1.0;
  glm::dvec4 base{1.0};
  bool volume = false;
};

bool read_factors(const json& g, const tinygltf::Material& material, GltfFactors& f,
                  std::string& what) {
  f.metallic = material.pbrMetallicRoughness.metallicFactor;
  f.roughness = material.pbrMetallicRoughness.roughnessFactor;
  const std::vector<double>& base = material.pbrMetallicRoughness.baseColorFactor;
  for (size_t k = 0; k < 4 && k < base.size(); ++k)
    f.base[int(k)] = std::clamp(base[k], 0.0, kMaxColorComponent);
  f.volume = json_at(g, {"extensions", "KHR_materials_volume"}) != nullptr;
  return number_at(g, {"extensions", "KHR_materials_transmission", "transmissionFactor"}, 0.0, 0.0,
                   1.0, "[0, 1]", f.transmission, what) &&
         number_at(g, {"extensions", "KHR_materials_ior", "ior"}, 1.5, kMinIor, kMaxIor,
                   "[1e-6, 1e6]", f.ior, what) &&
         number_at(g, {"extensions", "KHR_materials_volume", "attenuationDistance"}, 1e300, 1e-15,
                   1e300, "[1e-15, 1e300]", f.distance, what) &&
         number_at(g, {"extensions", "KHR_materials_volume", "thicknessFactor"}, 0.0, 0.0, 1e300,
                   "[0, 1e300]", f.thickness, what);
}

/// Beer-Lambert absorption of the volume: -ln(attenuationColor) / attenuationDistance.
glm::vec3 absorption(const json& g, double distance) {
  glm::vec3 out(0.0f);
  const json* c = json_at(g, {"extensions", "KHR_materials_volume", "attenuationColor"});
  for (int k = 0; k < 3 && c != nullptr && c->is_array() && size_t(k) < c->size(); ++k) {
    const double color = (*c)[size_t(k)].is_number() ? (*c)[size_t(k)].get<double>() : 1.0;
    out[k] =
        float(std::clamp(-std::log(std::max(color, 1e-300)) / distance, 0.0, kMaxColorComponent));
  }
  return out;
}

/// What gfield does not render of `material` whatever its kind.
void common_approximations(const tinygltf::Model& model, const tinygltf::Material& material,
                           std::vector<std::string>& notes) {
  const std::vector<double>& e = material.emissiveFactor;
  if (material.emissiveTexture.index >= 0 ||
      std::any_of(e.begin(), e.end(), [](double v) { return v > 0.0; }))
    notes.push_back("emission ignored");
  if (material.normalTexture.index >= 0)
    notes.push_back("normalTexture ignored");
  if (material.occlusionTexture.index >= 0)
    notes.push_back("occlusionTexture ignored");
  const std::vector<double>& base = material.pbrMetallicRoughness.baseColorFactor;
  if (material.alphaMode != "OPAQUE" || (base.size() == 4 && base[3] < 1.0))
    notes.push_back("alpha ignored (alphaMode " + material.alphaMode + "; rendered opaque)");
  const int texture = material.pbrMetallicRoughness.baseColorTexture.index;
  const int sampler = texture >= 0 ? model.textures[size_t(texture)].sampler : -1;
  if (sampler >= 0) {
    const tinygltf::Sampler& s = model.samplers[size_t(sampler)];
    if (s.wrapS != TINYGLTF_TEXTURE_WRAP_REPEAT || s.wrapT != TINYGLTF_TEXTURE_WRAP_REPEAT)
      notes.push_back("the base colour texture's sampler wraps as REPEAT (not as the file says)");
    if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST)
      notes.push_back("the base colour texture is read bilinearly (magFilter NEAREST)");
  }
}

/// The dielectric of a transmissive material; false with `what` for a thin-walled one.
bool dielectric(const json& g, const tinygltf::Material& material, const GltfFactors& f,
                Material& m, std::vector<std::string>& notes, std::string& what) {
  if (!f.volume || !(f.thickness > 0.0)) {
    what =
        "KHR_materials_transmission without KHR_materials_volume thicknessFactor > 0 is a "
        "thin-walled surface, which gfield does not render (its dielectrics are closed "
        "solids; a JSON scene refuses a dielectric quad likewise)";
    return false;
  }
  m.type = MaterialType::kDielectric;
  m.texture = TextureType::kNone;
  m.ior = float(f.ior);
  m.absorption = absorption(g, f.distance);
  if (f.transmission < 1.0)
    notes.push_back("transmissionFactor " + double_text(f.transmission) +
                    " rendered as full transmission");
  if (f.roughness > 0.05)
    notes.push_back("roughnessFactor " + double_text(f.roughness) + " rendered smooth");
  if (glm::any(glm::notEqual(glm::dvec3(f.base), glm::dvec3(1.0))) ||
      material.pbrMetallicRoughness.baseColorTexture.index >= 0)
    notes.push_back("base colour tint ignored (absorption comes from KHR_materials_volume)");
  if (json_at(g, {"extensions", "KHR_materials_transmission", "transmissionTexture"}) != nullptr)
    notes.push_back("transmissionTexture ignored");
  return true;
}

/// The mirror of a smooth metal.
void mirror(const tinygltf::Material& material, const GltfFactors& f, Material& m,
            std::vector<std::string>& notes) {
  m.type = MaterialType::kMirror;
  m.texture = TextureType::kNone;
  m.color = glm::vec3(f.base);
  if (f.metallic < 1.0)
    notes.push_back("metallicFactor " + double_text(f.metallic) + " rendered as a full mirror");
  if (f.roughness > 0.05)
    notes.push_back("roughnessFactor " + double_text(f.roughness) +
                    " rendered as a perfect mirror (gfield has no glossy reflection)");
  if (material.pbrMetallicRoughness.baseColorTexture.index >= 0)
    notes.push_back("baseColorTexture ignored (the factor alone tints the mirror)");
}

}  // namespace

bool gltf_object_material(const GltfDocument& d, int index, Material& m,
                          std::vector<std::string>& warnings, std::string& error) {
  m = Material{};
  m.type = MaterialType::kDiffuse;
  m.texture = TextureType::kMesh;
  m.color = glm::vec3(1.0f);
  if (index < 0)
    return true;
  const json& g = d.json["materials"][size_t(index)];
  const tinygltf::Material& material = d.model.materials[size_t(index)];
  const std::string place = d.file + ": materials[" + std::to_string(index) + "]" +
                            (material.name.empty() ? "" : " '" + printable(material.name) + "'");
  GltfFactors f;
  std::vector<std::string> notes;
  std::string what;
  std::string kind = "diffuse";
  if (!read_factors(g, material, f, what) ||
      (f.transmission > 0.0 && !dielectric(g, material, f, m, notes, what))) {
    error = place + ": " + what;
    return false;
  }
  if (f.transmission > 0.0) {
    kind = "a dielectric";
  } else if (f.metallic >= 0.5 && f.roughness <= 0.5) {
    kind = "a mirror";
    mirror(material, f, m, notes);
  } else if (f.metallic > 0.0) {
    notes.push_back("metallicFactor " + double_text(f.metallic) + " with roughnessFactor " +
                    double_text(f.roughness) + " rendered diffuse");
  }
  common_approximations(d.model, material, notes);
  if (notes.empty())
    return true;
  std::string line = place + ": rendered as " + kind + ": ";
  for (size_t k = 0; k < notes.size(); ++k)
    line += (k ? "; " : "") + notes[k];
  warnings.push_back(line);
  return true;
}

}  // namespace gfield
