#include "runtime/asset_memory.hpp"

#include <cstdio>
#include <filesystem>

namespace gfield {

std::string asset_memory_lines(const Scene& scene, const GpuAssets& assets) {
  std::string text;
  const char* format = assets.field_bits() == 8    ? "RG8"
                       : assets.field_bits() == 16 ? "RG16"
                                                   : "RG32F";
  for (size_t m = 0; m < assets.assets().size() && m < scene.meshes.size(); ++m) {
    const GpuAsset& a = assets.assets()[m];
    char part[128];
    std::string parts;
    if (a.layer >= 0) {
      std::snprintf(part, sizeof(part), "image %.1f MB", double(a.image_bytes) / 1e6);
      parts += part;
    }
    if (a.samples_per_side > 0) {
      std::snprintf(part, sizeof(part), ", field %s + line table %.1f MB (up to %d hits a line)",
                    format, double(a.field_bytes) / 1e6, a.field_layers);
      parts += part;
    }
    if (a.bvh_root >= 0) {
      std::snprintf(part, sizeof(part), ", BVH %.1f MB", double(a.bvh_bytes) / 1e6);
      parts += part;
    }
    if (parts.rfind(", ", 0) == 0)
      parts.erase(0, 2);
    text += std::filesystem::path(scene.meshes[m].file).filename().string() + ": " +
            (parts.empty() ? "nothing loaded" : parts) + "\n";
  }
  return text;
}

}  // namespace gfield
