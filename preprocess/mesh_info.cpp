#include "preprocess/mesh_info.hpp"

#include "geometry/mesh_appearance.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

/// What the mesh carries besides its shape.
nlohmann::json appearance_to_json(const MeshAppearance& a) {
  nlohmann::json textures = nlohmann::json::array();
  for (const MeshTexture& t : a.textures) {
    textures.push_back(
        {{"name", printable(t.name)}, {"width", t.image.width}, {"height", t.image.height}});
  }
  return {{"texture_coordinates", !a.corner_uv.empty()},
          {"vertex_colors", !a.vertex_color.empty()},
          {"materials", a.materials.size()},
          {"textures", textures},
          {"base_color", carries_base_color(a)}};
}

}  // namespace

bool read_mesh_info(const MeshSource& source, MeshInfo& info, std::vector<std::string>& warnings,
                    std::string& error) {
  MeshSource headers_only = source;
  headers_only.texture_pixels = false;
  TriangleMesh mesh;
  MeshAppearance appearance;
  if (!load_mesh(headers_only, mesh, &appearance, warnings, error, &info.stats)) {
    return false;
  }
  info.topology = analyze_topology(mesh);
  info.appearance = appearance_to_json(appearance);
  return true;
}

nlohmann::json mesh_info_to_json(const MeshInfo& info, const std::string& file) {
  nlohmann::json j = topology_to_json(info.topology);
  j["file"] = printable(file);
  j["polygons"] = info.stats.polygons;
  j["triangulated_polygons"] = info.stats.triangulated;
  j["appearance"] = info.appearance;
  return j;
}

}  // namespace gfield
