// gfield info MESH [--json]: the topology report of a mesh file.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "geometry/mesh_io.hpp"
#include "gfield/printable.hpp"
#include "preprocess/cli/commands.hpp"
#include "preprocess/topology.hpp"

namespace gfield {

void add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "info",
      "Read a mesh (OBJ/PLY/OFF/STL) and print its topology: vertices, faces, components,\n"
      "boundary loops, non-manifold edges and vertices, degenerate faces, Euler\n"
      "characteristic and genus per component, bounding box.");
  auto mesh_path = std::make_shared<std::string>();
  auto as_json = std::make_shared<bool>(false);
  cmd->add_option("MESH", *mesh_path, "mesh file (.obj, .ply, .off, .stl)")->required();
  cmd->add_flag("--json", *as_json, "print the report as JSON on stdout");
  cmd->callback([mesh_path, as_json] {
    TriangleMesh mesh;
    MeshLoadStats stats;
    std::string error;
    if (!load_mesh(*mesh_path, mesh, error, &stats)) {
      throw CommandError(error);
    }
    const TopologyReport report = analyze_topology(mesh);
    if (*as_json) {
      nlohmann::json j = topology_to_json(report);
      j["file"] = printable(*mesh_path);
      j["polygons"] = stats.polygons;
      j["triangulated_polygons"] = stats.triangulated;
      std::printf("%s\n", j.dump(2).c_str());
    } else {
      std::printf("mesh               %s\n", printable(*mesh_path).c_str());
      if (stats.triangulated > 0) {
        std::printf("polygons           %zu (%zu with more than 3 corners, triangulated)\n",
                    stats.polygons, stats.triangulated);
      }
      std::printf("%s", topology_to_text(report).c_str());
    }
  });
}

}  // namespace gfield
