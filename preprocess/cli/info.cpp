// gfield info MESH [--json]: the topology report of a mesh file.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "gfield/printable.hpp"
#include "preprocess/cli/commands.hpp"
#include "preprocess/cli/path_options.hpp"
#include "preprocess/mesh_info.hpp"

namespace gfield {
namespace {

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
  cmd->add_option("MESH", *mesh_path, mesh_file_help())->required();
  cmd->add_option("--mesh", *part, "glTF: the mesh NAME (or #INDEX) (default: the whole scene)");
  cmd->add_flag("--json", *as_json, "print the report as JSON on stdout");
  add_outside_paths_option(cmd, *allow_outside);
  cmd->callback([mesh_path, part, as_json, allow_outside] {
    MeshInfo info;
    std::vector<std::string> warnings;
    std::string error;
    if (!read_mesh_info(MeshSource{*mesh_path, *part, outside_paths(*allow_outside)}, info,
                        warnings, error)) {
      throw CommandError(error);
    }
    print_warnings(warnings);
    if (*as_json) {
      std::printf("%s\n", mesh_info_to_json(info, *mesh_path).dump(2).c_str());
    } else {
      std::printf("mesh               %s\n", printable(*mesh_path).c_str());
      if (info.stats.triangulated > 0) {
        std::printf("polygons           %zu (%zu with more than 3 corners, triangulated)\n",
                    info.stats.polygons, info.stats.triangulated);
      }
      std::printf("%s", topology_to_text(info.topology).c_str());
      std::printf("appearance         %s\n", appearance_text(info.appearance).c_str());
    }
  });
}

}  // namespace gfield
