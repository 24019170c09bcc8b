// The base-colour materials and textures of a glTF document (gltf_document.hpp).

#include <filesystem>
#include <map>

#include "geometry/gltf_checks.hpp"
#include "geometry/gltf_document.hpp"
#include "geometry/mesh_appearance.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// Decodes image `index` of the document into the next texture of `appearance` (with `pixels`
/// false: its header only): embedded bytes (a buffer view, a data URI, or an external file
/// tinygltf read) must be an image within the texture budget; an external file that is missing
/// gives mid-grey and a warning.
bool decode_gltf_image(const GltfDocument& d, int index, bool pixels, MeshAppearance& appearance,
                       std::vector<std::string>& warnings, std::string& error) {
  const tinygltf::Image& image = d.model.images[size_t(index)];
  const std::string name = d.file + ": images[" + std::to_string(index) + "]";
  if (image.image.empty() && image.uri.empty()) {
    error = name + ": no image data";
    return false;
  }
  if (image.image.empty()) {  // an external file tinygltf did not find: the usual warning
    const std::string file =
        (std::filesystem::path(d.file).parent_path() / decode_uri(image.uri)).string();
    return load_texture_files(d.file, {file}, pixels, appearance, warnings, error);
  }
  MeshTexture texture{name, Image()};
  const unsigned char* bytes = image.image.data();
  const size_t size = image.image.size();
  int width = 0, height = 0;
  if (!decode_image_size(name, bytes, size, width, height, error) ||
      (pixels && (!check_texture_budget(name, width, height, appearance, error) ||
                  !decode_image(name, bytes, size, texture.image, error))))
    return false;
  texture.image.width = width;
  texture.image.height = height;
  appearance.textures.push_back(std::move(texture));
  return true;
}

/// Material `m`'s base colour; its texture's image (-1: none) in `image` (the texture's
/// coordinates, with their texCoord set and KHR_texture_transform, were read per primitive).
BaseColorMaterial base_color_material(const GltfDocument& d, size_t m, int& image) {
  const tinygltf::Material& material = d.model.materials[m];
  const std::vector<double>& f = material.pbrMetallicRoughness.baseColorFactor;
  BaseColorMaterial out;
  out.name = material.name;
  if (f.size() >= 3)
    out.factor = glm::clamp(glm::vec3(float(f[0]), float(f[1]), float(f[2])), glm::vec3(0.0f),
                            glm::vec3(float(kMaxColorComponent)));
  const tinygltf::TextureInfo& info = material.pbrMetallicRoughness.baseColorTexture;
  image = info.index >= 0 ? d.model.textures[size_t(info.index)].source : -1;
  return out;
}

}  // namespace

bool gltf_appearance(const GltfDocument& d, bool any_uv, bool any_color, bool any_material,
                     bool pixels, MeshAppearance& appearance, std::vector<std::string>& warnings,
                     std::string& error) {
  if (!any_uv)
    appearance.corner_uv.clear();
  if (!any_color)
    appearance.vertex_color.clear();
  if (!any_material) {
    appearance.face_material.clear();
    return true;
  }
  std::vector<char> used(d.model.materials.size(), 0);
  for (const int m : appearance.face_material)
    if (m >= 0)
      used[size_t(m)] = 1;
  std::map<int, int> textures;  // glTF image -> appearance texture
  for (size_t m = 0; m < d.model.materials.size(); ++m) {
    int image = -1;
    appearance.materials.push_back(base_color_material(d, m, image));
    if (image < 0 || !used[m])
      continue;
    const auto [it, added] = textures.emplace(image, int(appearance.textures.size()));
    if (added && !decode_gltf_image(d, image, pixels, appearance, warnings, error))
      return false;
    appearance.materials.back().texture = it->second;
  }
  return true;
}

}  // namespace gfield
