#pragma once
// What `gfield info` reports of a mesh file (gfield.info in Python): the file as it stores the
// mesh (no welding, no repair), its topology, and what it carries besides its shape (texture
// coordinates, vertex colours, materials, textures' sizes read from their headers).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/mesh_io.hpp"
#include "preprocess/topology.hpp"

namespace gfield {

struct MeshInfo {
  TopologyReport topology;
  MeshLoadStats stats;
  /// texture_coordinates, vertex_colors (bool), materials (count), textures [{name, width,
  /// height}], base_color (bool: carries_base_color).
  nlohmann::json appearance;
};

/// Reads `source` (its textures' headers only, whatever source.texture_pixels says) and analyses
/// its topology. False with the reader's one-line error "FILE[:LINE]: problem"; `warnings`
/// receives what the reader went on past (a missing texture, ...).
bool read_mesh_info(const MeshSource& source, MeshInfo& info, std::vector<std::string>& warnings,
                    std::string& error);

/// The `gfield info --json` report: topology_to_json plus file (printable), polygons,
/// triangulated_polygons and appearance.
nlohmann::json mesh_info_to_json(const MeshInfo& info, const std::string& file);

}  // namespace gfield
