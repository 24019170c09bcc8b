// gfield info MESH [--json]: the topology report of a mesh file.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/printable.hpp"
#include "preprocess/cli/commands.hpp"
#include "preprocess/cli/path_options.hpp"
#include "preprocess/topology.hpp"

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

std::string appearance_text(const nlohmann::json& j) {
  if (!j["base_color"].get<bool>() && !j["texture_coordinates"].get<bool>()) {
    return "no texture coordinates, no base colour";
  }
  std::string text = j["texture_coordinates"].get<bool>() ? "texture coordinates" : "no uvs";
  text += ", " + std::to_string(j["materials"].get<size_t>()) + " materials";
  for (const auto& t : j["textures"]) {
    text += ", texture " + t["name"].get<std::string>() + " (" +
            std::to_string(t["width"].get<int>()) + "x" + std::to_string(t["height"].get<int>()) +
            ")";
  }
  return text + (j["vertex_colors"].get<bool>() ? ", vertex colours" : "");
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "info",
      "Read a mesh (OBJ/PLY/OFF/STL/glTF) and print its topology: vertices, faces, components,\n"
      "boundary loops, non-manifold edges and vertices, degenerate faces, Euler\n"
      "characteristic and genus per component, bounding box.");
  auto mesh_path = std::make_shared<std::string>();
  auto part = std::make_shared<std::string>();
  auto as_json = std::make_shared<bool>(false);
  auto allow_outside = std::make_shared<bool>(false);
  cmd->add_option("MESH", *mesh_path, "mesh file (.obj, .ply, .off, .stl, .gltf, .glb)")
      ->required();
  cmd->add_option("--mesh", *part, "glTF: the mesh NAME (or #INDEX) (default: the whole scene)");
  cmd->add_flag("--json", *as_json, "print the report as JSON on stdout");
  add_outside_paths_option(cmd, *allow_outside);
  cmd->callback([mesh_path, part, as_json, allow_outside] {
    TriangleMesh mesh;
    MeshAppearance appearance;
    MeshLoadStats stats;
    std::vector<std::string> warnings;
    std::string error;
    // The textures' sizes are reported, not their pixels: their headers are read, not decoded.
    const MeshSource source{*mesh_path, *part, outside_paths(*allow_outside), false};
    if (!load_mesh(source, mesh, &appearance, warnings, error, &stats)) {
      throw CommandError(error);
    }
    print_warnings(warnings);
    const TopologyReport report = analyze_topology(mesh);
    const nlohmann::json surface = appearance_to_json(appearance);
    if (*as_json) {
      nlohmann::json j = topology_to_json(report);
      j["file"] = printable(*mesh_path);
      j["polygons"] = stats.polygons;
      j["triangulated_polygons"] = stats.triangulated;
      j["appearance"] = surface;
      std::printf("%s\n", j.dump(2).c_str());
    } else {
      std::printf("mesh               %s\n", printable(*mesh_path).c_str());
      if (stats.triangulated > 0) {
        std::printf("polygons           %zu (%zu with more than 3 corners, triangulated)\n",
                    stats.polygons, stats.triangulated);
      }
      std::printf("%s", topology_to_text(report).c_str());
      std::printf("appearance         %s\n", appearance_text(surface).c_str());
    }
  });
}

}  // namespace gfield
