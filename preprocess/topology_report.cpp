// A topology report (topology.hpp) as JSON, back from JSON, and as text.

#include <cstdio>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "preprocess/topology.hpp"

namespace gfield {

namespace {

nlohmann::json vec_json(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}

std::string describe_surface(const ComponentTopology& c) {
  if (c.non_manifold_edges > 0) {
    return "non-manifold (" + std::to_string(c.non_manifold_edges) +
           " edges with more than 2 faces)";
  }
  if (!c.oriented) {
    return "manifold, not consistently oriented";
  }
  std::string s = c.boundary_loops == 0 ? "closed" : "open";
  s += ", genus " + std::to_string(c.genus);
  if (c.boundary_loops > 0) {
    s += ", " + std::to_string(c.boundary_loops) + " boundary loop" +
         (c.boundary_loops == 1 ? "" : "s");
  }
  if (c.genus == 0 && c.boundary_loops == 0) {
    s += " (sphere)";
  } else if (c.genus == 0 && c.boundary_loops == 1) {
    s += " (disk)";
  }
  if (c.non_manifold_vertices > 0) {
    s += ", " + std::to_string(c.non_manifold_vertices) + " pinched vertices (split)";
  }
  return s;
}

}  // namespace

namespace {

glm::dvec3 vec_from_json(const nlohmann::json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

/// The figures a component and the whole mesh both have (ComponentTopology, TopologyReport).
template <class Counts>
nlohmann::json counts_to_json(const Counts& c) {
  return {{"vertices", c.vertices},
          {"edges", c.edges},
          {"faces", c.faces},
          {"boundary_edges", c.boundary_edges},
          {"boundary_loops", c.boundary_loops},
          {"non_manifold_edges", c.non_manifold_edges},
          {"non_manifold_vertices", c.non_manifold_vertices},
          {"euler_characteristic", c.euler_characteristic},
          {"area", c.area},
          {"bounds", {{"min", vec_json(c.bounds_min)}, {"max", vec_json(c.bounds_max)}}}};
}

template <class Counts>
void counts_from_json(const nlohmann::json& j, Counts& c) {
  c.vertices = j.at("vertices").get<size_t>();
  c.edges = j.at("edges").get<size_t>();
  c.faces = j.at("faces").get<size_t>();
  c.boundary_edges = j.at("boundary_edges").get<size_t>();
  c.boundary_loops = j.at("boundary_loops").get<size_t>();
  c.non_manifold_edges = j.at("non_manifold_edges").get<size_t>();
  c.non_manifold_vertices = j.at("non_manifold_vertices").get<size_t>();
  c.euler_characteristic = j.at("euler_characteristic").get<long>();
  c.area = j.at("area").get<double>();
  c.bounds_min = vec_from_json(j.at("bounds").at("min"));
  c.bounds_max = vec_from_json(j.at("bounds").at("max"));
}

}  // namespace

nlohmann::json topology_to_json(const TopologyReport& r) {
  nlohmann::json j = counts_to_json(r);
  j["unreferenced_vertices"] = r.unreferenced_vertices;
  j["duplicate_positions"] = r.duplicate_positions;
  j["degenerate_faces"] = r.degenerate_faces;
  j["closed"] = r.closed();
  j["manifold"] = r.manifold();
  j["components"] = nlohmann::json::array();
  for (const ComponentTopology& c : r.components) {
    nlohmann::json component = counts_to_json(c);
    component["oriented"] = c.oriented;
    component["genus"] = c.genus;
    component["surface"] = describe_surface(c);
    j["components"].push_back(std::move(component));
  }
  return j;
}

TopologyReport topology_from_json(const nlohmann::json& j) {
  TopologyReport r;
  counts_from_json(j, r);
  r.unreferenced_vertices = j.at("unreferenced_vertices").get<size_t>();
  r.duplicate_positions = j.at("duplicate_positions").get<size_t>();
  r.degenerate_faces = j.at("degenerate_faces").get<size_t>();
  for (const nlohmann::json& c : j.at("components")) {
    ComponentTopology component;
    counts_from_json(c, component);
    component.oriented = c.at("oriented").get<bool>();
    component.genus = c.at("genus").get<long>();
    r.components.push_back(component);
  }
  return r;
}

std::string topology_to_text(const TopologyReport& r) {
  std::ostringstream s;
  char line[256];
  s << "vertices           " << r.vertices;
  if (r.unreferenced_vertices > 0) {
    s << " (" << r.unreferenced_vertices << " unreferenced)";
  }
  if (r.duplicate_positions > 0) {
    s << " (" << r.duplicate_positions << " at the position of another vertex)";
  }
  s << "\nfaces              " << r.faces << " triangles";
  if (r.degenerate_faces > 0) {
    s << " (" << r.degenerate_faces << " degenerate)";
  }
  s << "\nedges              " << r.edges;
  s << "\nboundary           " << r.boundary_edges << " edges in " << r.boundary_loops << " loops";
  s << "\nnon-manifold       " << r.non_manifold_edges << " edges, " << r.non_manifold_vertices
    << " vertices";
  s << "\neuler              " << r.euler_characteristic;
  std::snprintf(line, sizeof line, "\nbounding box       (%.6g, %.6g, %.6g) - (%.6g, %.6g, %.6g)",
                r.bounds_min.x, r.bounds_min.y, r.bounds_min.z, r.bounds_max.x, r.bounds_max.y,
                r.bounds_max.z);
  s << line;
  const glm::dvec3 size = r.bounds_max - r.bounds_min;
  std::snprintf(line, sizeof line, "\nsize               %.6g x %.6g x %.6g, diagonal %.6g", size.x,
                size.y, size.z, glm::length(size));
  s << line;
  s << "\ncomponents         " << r.components.size();
  for (size_t i = 0; i < r.components.size(); ++i) {
    const ComponentTopology& c = r.components[i];
    std::snprintf(line, sizeof line, "\n  #%-3zu %7zu faces %7zu vertices  chi %-4ld  ", i, c.faces,
                  c.vertices, c.euler_characteristic);
    s << line << describe_surface(c);
  }
  s << '\n';
  return s.str();
}

}  // namespace gfield
