#include "geometry/gltf_mesh.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtx/compatibility.hpp>

#include "geometry/gltf_document.hpp"
#include "geometry/mesh_appearance.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// What the primitives read so far became.
struct GltfSoup {
  TriangleMesh mesh;
  MeshAppearance appearance;  ///< corner uvs, vertex colours, glTF material per face
  bool any_uv = false, any_color = false, any_material = false;
  size_t polygons = 0;
};

/// "meshes[M].primitives[P]: ".
std::string where(int mesh, size_t primitive) {
  return "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(primitive) + "]: ";
}

/// The accessor of attribute `name` (-1: none), refused when sparse or of the wrong type.
bool attribute(const GltfDocument& d, const tinygltf::Primitive& p, const char* name,
               std::initializer_list<int> types, int& accessor, std::string& what) {
  const auto found = p.attributes.find(name);
  accessor = found == p.attributes.end() ? -1 : found->second;
  if (accessor < 0) {
    return true;
  }
  const tinygltf::Accessor& a = d.model.accessors[size_t(accessor)];
  const bool type_ok = std::find(types.begin(), types.end(), a.type) != types.end();
  if (a.sparse.isSparse || !type_ok) {
    what = std::string(name) + ": accessor " + std::to_string(accessor) +
           (a.sparse.isSparse ? " is sparse (not supported)" : " has the wrong type");
    return false;
  }
  return true;
}

/// Triangles of a primitive's `indices` in `mode` (4 triangles, 5 strip, 6 fan).
std::vector<glm::ivec3> primitive_triangles(const std::vector<std::int64_t>& indices, int mode) {
  std::vector<glm::ivec3> triangles;
  const size_t n = indices.size();
  for (size_t k = 0; mode == 4 && k + 2 < n; k += 3)
    triangles.emplace_back(indices[k], indices[k + 1], indices[k + 2]);
  for (size_t k = 0; mode == 5 && k + 2 < n; ++k)  // strips alternate their winding
    triangles.push_back(k % 2 == 0 ? glm::ivec3(indices[k], indices[k + 1], indices[k + 2])
                                   : glm::ivec3(indices[k + 1], indices[k], indices[k + 2]));
  for (size_t k = 1; mode == 6 && k + 1 < n; ++k)
    triangles.emplace_back(indices[0], indices[k], indices[k + 1]);
  return triangles;
}

/// Appends the vertices of primitive `p` placed by `world`; false with `what` for a coordinate
/// out of range.
bool add_positions(const std::vector<float>& xyz, const glm::dmat4& world, GltfSoup& soup,
                   std::string& what) {
  for (size_t v = 0; v + 2 < xyz.size(); v += 3) {
    const glm::dvec3 p(world * glm::dvec4(xyz[v], xyz[v + 1], xyz[v + 2], 1.0));
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k]) || std::abs(p[k]) > kMaxCoordinate) {
        what = "POSITION: a coordinate is not finite or beyond the limit of 1e15";
        return false;
      }
    }
    soup.mesh.positions.emplace_back(glm::vec3(p));
  }
  return true;
}

/// Appends the vertex colours (COLOR_0, rgb of vec3 or vec4) of `count` vertices, or white.
bool add_colors(const GltfDocument& d, int accessor, size_t count, GltfSoup& soup,
                std::string& what) {
  std::vector<glm::vec3>& colors = soup.appearance.vertex_color;
  if (accessor < 0) {
    colors.resize(colors.size() + count, glm::vec3(1.0f));
    return true;
  }
  soup.any_color = true;
  const std::vector<float> values = read_accessor_floats(d, accessor);
  const size_t n = size_t(accessor_components(d.model.accessors[size_t(accessor)]));
  for (size_t v = 0; v < count; ++v) {
    const glm::vec3 c(values[v * n], values[v * n + 1], values[v * n + 2]);
    if (!(glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))) &&
          glm::all(glm::lessThanEqual(c, glm::vec3(float(kMaxColorComponent)))))) {
      what = "COLOR_0: a component is not in [0, 1e6]";
      return false;
    }
    colors.push_back(c);
  }
  return true;
}

/// The primitive's triangle corners' texture coordinates (TEXCOORD_0, v flipped), or (0, 0).
bool add_corner_uvs(const GltfDocument& d, int accessor, const std::vector<glm::ivec3>& triangles,
                    size_t first_vertex, GltfSoup& soup, std::string& what) {
  std::vector<float> uv;
  if (accessor >= 0) {
    soup.any_uv = true;
    uv = read_accessor_floats(d, accessor);
  }
  for (const glm::ivec3& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const size_t v = size_t(t[k]);
      const glm::vec2 c = uv.empty() ? glm::vec2(0.0f) : glm::vec2(uv[2 * v], 1.0f - uv[2 * v + 1]);
      if (!glm::all(glm::isfinite(c)) ||
          glm::any(glm::greaterThan(glm::abs(c), glm::vec2(float(kMaxTextureCoordinate))))) {
        what = "TEXCOORD_0: a texture coordinate is not finite or beyond the limit of 1e4";
        return false;
      }
      soup.appearance.corner_uv.push_back(c);
    }
  }
  (void)first_vertex;
  return true;
}

/// Appends primitive `p` of mesh `m` placed by `world`; `warnings` gets a POSITION accessor's
/// declared bounds that its data contradict.
bool add_primitive(const GltfDocument& d, int m, size_t index, const glm::dmat4& world,
                   GltfSoup& soup, std::vector<std::string>& warnings, std::string& what) {
  const tinygltf::Primitive& p = d.model.meshes[size_t(m)].primitives[index];
  const int mode = p.mode < 0 ? 4 : p.mode;
  int position = -1, uv = -1, color = -1;
  if (mode < 4 || mode > 6) {
    const char* names[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
    what = "primitive mode " + std::to_string(mode) +
           (mode >= 0 && mode < 4 ? std::string(" (") + names[mode] + ")" : std::string()) +
           " is not supported (triangles, strips and fans only)";
    return false;
  }
  if (!attribute(d, p, "POSITION", {TINYGLTF_TYPE_VEC3}, position, what) ||
      !attribute(d, p, "TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, uv, what) ||
      !attribute(d, p, "COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, color, what)) {
    return false;
  }
  if (position < 0 || (p.indices >= 0 && d.model.accessors[size_t(p.indices)].sparse.isSparse)) {
    what = position < 0 ? "no POSITION attribute" : "sparse indices (not supported)";
    return false;
  }
  const size_t vertices = d.model.accessors[size_t(position)].count;
  const auto attribute_count = [&](int a) {
    return a < 0 || d.model.accessors[size_t(a)].count >= vertices;
  };
  if (!attribute_count(uv) || !attribute_count(color)) {
    what = "TEXCOORD_0 or COLOR_0 has fewer elements than POSITION";
    return false;
  }
  std::vector<std::int64_t> indices;
  if (p.indices >= 0) {
    indices = read_accessor_integers(d, p.indices);
  } else {
    for (size_t v = 0; v < vertices; ++v)
      indices.push_back(std::int64_t(v));
  }
  for (const std::int64_t i : indices) {
    if (i < 0 || size_t(i) >= vertices) {
      what = "index " + std::to_string(i) + " out of range (" + std::to_string(vertices) +
             " vertices)";
      return false;
    }
  }
  const std::vector<glm::ivec3> triangles = primitive_triangles(indices, mode);
  if (soup.mesh.triangles.size() + triangles.size() > size_t(kMaxMeshTriangles) ||
      soup.mesh.positions.size() + vertices > size_t(kMaxMeshVertices)) {
    what = "more than " + std::to_string(kMaxMeshTriangles) + " triangles or vertices in all";
    return false;
  }
  const size_t first = soup.mesh.positions.size();
  const std::vector<float> xyz = read_accessor_floats(d, position);
  glm::dvec3 lo, hi;
  position_bounds(xyz, lo, hi);
  check_declared_bounds(d, position, lo, hi, warnings);
  if (!add_positions(xyz, world, soup, what) || !add_colors(d, color, vertices, soup, what) ||
      !add_corner_uvs(d, uv, triangles, first, soup, what)) {
    return false;
  }
  for (const glm::ivec3& t : triangles) {
    soup.mesh.triangles.push_back(t + glm::ivec3(int(first)));
    soup.appearance.face_material.push_back(p.material);
  }
  soup.any_material = soup.any_material || p.material >= 0;
  soup.polygons += triangles.size();
  return true;
}

/// The mesh `part` names: "#INDEX" or a name. False with `error` listing the meshes.
bool find_mesh(const GltfDocument& d, const std::string& part, int& mesh, std::string& error) {
  const std::vector<tinygltf::Mesh>& meshes = d.model.meshes;
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (meshes[m].name == part || part == gltf_mesh_part(int(m))) {
      mesh = int(m);
      return true;
    }
  }
  std::string names;
  for (size_t m = 0; m < meshes.size() && m < 20; ++m)
    names += (m ? ", " : "") + (meshes[m].name.empty() ? gltf_mesh_part(int(m)) : meshes[m].name);
  error = d.file + ": no mesh " + part + " (its meshes: " + (names.empty() ? "none" : names) +
          (meshes.size() > 20 ? ", ..." : "") + ")";
  return false;
}

/// The meshes to read and where: `part`'s mesh at the origin, or every mesh node of the scene
/// (every mesh at the origin when no node places one).
bool placements(const GltfDocument& d, const std::string& part,
                std::vector<std::pair<int, glm::dmat4>>& out, std::string& error) {
  int mesh = -1;
  if (!part.empty()) {
    if (!find_mesh(d, part, mesh, error))
      return false;
    out.emplace_back(mesh, glm::dmat4(1.0));
    return true;
  }
  std::vector<PlacedNode> nodes;
  if (!scene_nodes(d, nodes, error))
    return false;
  for (const PlacedNode& n : nodes)
    if (d.model.nodes[size_t(n.node)].mesh >= 0)
      out.emplace_back(d.model.nodes[size_t(n.node)].mesh, n.world);
  for (size_t m = 0; out.empty() && m < d.model.meshes.size(); ++m)
    out.emplace_back(int(m), glm::dmat4(1.0));
  return true;
}

}  // namespace

std::string gltf_mesh_part(int index) {
  return "#" + std::to_string(index);
}

bool load_gltf_mesh(const MeshSource& source, TriangleMesh& mesh, MeshAppearance* appearance,
                    std::vector<std::string>& warnings, std::string& error, MeshLoadStats* stats) {
  GltfDocument d;
  std::vector<std::pair<int, glm::dmat4>> placed;
  if (!load_gltf_document(source.file, source.outside_paths, d, error) ||
      !placements(d, source.part, placed, error))
    return false;
  GltfSoup soup;
  for (const auto& [m, world] : placed) {
    for (size_t p = 0; p < d.model.meshes[size_t(m)].primitives.size(); ++p) {
      std::string what;
      if (!add_primitive(d, m, p, world, soup, warnings, what)) {
        error = source.file + ": " + where(m, p) + what;
        return false;
      }
    }
  }
  if (soup.mesh.triangles.empty()) {
    error = source.file + ": no triangles" + (source.part.empty() ? "" : " in mesh " + source.part);
    return false;
  }
  if (appearance != nullptr &&
      !gltf_appearance(d, soup.any_uv, soup.any_color, soup.any_material, source.texture_pixels,
                       soup.appearance, warnings, error))
    return false;
  if (appearance != nullptr)
    *appearance = std::move(soup.appearance);
  mesh = std::move(soup.mesh);
  if (stats)
    *stats = MeshLoadStats{soup.polygons, 0};
  return true;
}

}  // namespace gfield
