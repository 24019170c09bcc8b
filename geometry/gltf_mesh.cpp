#include "geometry/gltf_mesh.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtx/compatibility.hpp>

#include "geometry/gltf_document.hpp"
#include "geometry/gltf_texture_transform.hpp"
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

/// "SHORT" ... for glTF component type `type`, with " normalized" when `normalized`.
std::string component_name(int type, bool normalized) {
  const char* names[] = {"BYTE", "UNSIGNED_BYTE", "SHORT", "UNSIGNED_SHORT",
                         "",     "UNSIGNED_INT",  "FLOAT"};
  const int k = type - TINYGLTF_COMPONENT_TYPE_BYTE;
  return std::string(k >= 0 && k < 7 ? names[k] : "an unknown component type") +
         (normalized ? " normalized" : "");
}

/// Whether the glTF specification allows accessor `a` for attribute `name` (POSITION,
/// TEXCOORD_n, COLOR_0): floats, normalised unsigned bytes and shorts for uvs and colours, and
/// with KHR_mesh_quantization (`quantized`) bytes and shorts of either kind for positions and uvs.
bool component_type_allowed(const std::string& name, const tinygltf::Accessor& a, bool quantized) {
  const int t = a.componentType;
  const bool n = a.normalized;
  const bool small_integer =
      t >= TINYGLTF_COMPONENT_TYPE_BYTE && t <= TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  const bool unsigned_normalized = n && (t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                         t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  if (t == TINYGLTF_COMPONENT_TYPE_FLOAT)
    return !n;
  if (name == "POSITION")
    return quantized && small_integer;
  if (name == "COLOR_0")
    return unsigned_normalized;
  return unsigned_normalized || (quantized && small_integer);  // TEXCOORD_n
}

/// The accessor of attribute `name` (-1: none), refused when sparse, of the wrong type or of a
/// component type the specification does not allow for it.
bool attribute(const GltfDocument& d, const tinygltf::Primitive& p, const std::string& name,
               std::initializer_list<int> types, int& accessor, std::string& what) {
  const auto found = p.attributes.find(name);
  accessor = found == p.attributes.end() ? -1 : found->second;
  if (accessor < 0) {
    return true;
  }
  const tinygltf::Accessor& a = d.model.accessors[size_t(accessor)];
  const bool type_ok = std::find(types.begin(), types.end(), a.type) != types.end();
  const bool quantized = uses_extension(d, "KHR_mesh_quantization");
  if (a.sparse.isSparse || !type_ok) {
    what = name + ": accessor " + std::to_string(accessor) +
           (a.sparse.isSparse ? " is sparse (not supported)" : " has the wrong type");
    return false;
  }
  if (!component_type_allowed(name, a, quantized)) {
    what = name + ": accessor " + std::to_string(accessor) + " is " +
           component_name(a.componentType, a.normalized) + ", which glTF " +
           (component_type_allowed(name, a, true)
                ? "allows only with KHR_mesh_quantization (not in extensionsUsed)"
                : "does not allow for " + name);
    return false;
  }
  return true;
}

/// The primitive's index accessor: UNSIGNED_BYTE, _SHORT or _INT, not normalized (glTF 2.0).
bool check_indices(const GltfDocument& d, const tinygltf::Primitive& p, std::string& what) {
  if (p.indices < 0)
    return true;
  const tinygltf::Accessor& a = d.model.accessors[size_t(p.indices)];
  const int t = a.componentType;
  const bool ok =
      !a.normalized && !a.sparse.isSparse && a.type == TINYGLTF_TYPE_SCALAR &&
      (t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
       t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  if (!ok)
    what = "indices: accessor " + std::to_string(p.indices) + " is " +
           (a.sparse.isSparse ? std::string("sparse (not supported)")
                              : component_name(t, a.normalized) +
                                    " (glTF indices are scalar UNSIGNED_BYTE, _SHORT or _INT)");
  return ok;
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

/// The primitive's triangle corners' texture coordinates (`accessor`: TEXCOORD_n, through
/// `transform`, v flipped), or (0, 0) without one.
bool add_corner_uvs(const GltfDocument& d, int accessor, const TextureTransform& transform,
                    const std::vector<glm::ivec3>& triangles, GltfSoup& soup, std::string& what) {
  std::vector<float> uv;
  if (accessor >= 0) {
    soup.any_uv = true;
    uv = read_accessor_floats(d, accessor);
  }
  for (const glm::ivec3& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const size_t v = size_t(t[k]);
      const glm::dvec2 c =
          uv.empty() ? glm::dvec2(0.0) : transformed_uv(transform, {uv[2 * v], uv[2 * v + 1]});
      if (!glm::all(glm::isfinite(c)) ||
          glm::any(glm::greaterThan(glm::abs(c), glm::dvec2(kMaxTextureCoordinate)))) {
        what = "TEXCOORD_" + std::to_string(transform.tex_coord) +
               ": a texture coordinate is not finite or beyond the limit of 1e4" +
               (transform.transformed ? " (after KHR_texture_transform)" : "");
        return false;
      }
      soup.appearance.corner_uv.push_back(glm::vec2(c));
    }
  }
  return true;
}

/// The texture transform of the base colour texture of material `m` (-1: none; identity).
bool material_uv_transform(const GltfDocument& d, int m, TextureTransform& transform,
                           std::string& what) {
  transform = TextureTransform{};
  const nlohmann::json* info =
      m < 0 ? nullptr
            : json_at(d.json["materials"][size_t(m)], {"pbrMetallicRoughness", "baseColorTexture"});
  if (info == nullptr || texture_transform(*info, transform, what))
    return true;
  what = "materials[" + std::to_string(m) + "].pbrMetallicRoughness.baseColorTexture." + what;
  return false;
}

/// Appends primitive `p` of mesh `m` placed by `world`; `warnings` gets a POSITION accessor's
/// declared bounds that its data contradict.
bool add_primitive(const GltfDocument& d, int m, size_t index, const glm::dmat4& world,
                   GltfSoup& soup, std::vector<std::string>& warnings, std::string& what) {
  const tinygltf::Primitive& p = d.model.meshes[size_t(m)].primitives[index];
  const int mode = p.mode < 0 ? 4 : p.mode;
  int position = -1, uv = -1, color = -1;
  TextureTransform transform;
  if (mode < 4 || mode > 6) {
    const char* names[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
    what = "primitive mode " + std::to_string(mode) +
           (mode >= 0 && mode < 4 ? std::string(" (") + names[mode] + ")" : std::string()) +
           " is not supported (triangles, strips and fans only)";
    return false;
  }
  if (!material_uv_transform(d, p.material, transform, what) ||
      !attribute(d, p, "POSITION", {TINYGLTF_TYPE_VEC3}, position, what) ||
      !attribute(d, p, "TEXCOORD_" + std::to_string(transform.tex_coord), {TINYGLTF_TYPE_VEC2}, uv,
                 what) ||
      !attribute(d, p, "COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, color, what) ||
      !check_indices(d, p, what)) {
    return false;
  }
  if (position < 0) {
    what = "no POSITION attribute";
    return false;
  }
  if (uv < 0 && p.material >= 0 &&
      json_at(d.json["materials"][size_t(p.material)],
              {"pbrMetallicRoughness", "baseColorTexture"}))
    warnings.push_back(d.file + ": meshes[" + std::to_string(m) + "].primitives[" +
                       std::to_string(index) +
                       "]: its material's base colour texture reads TEXCOORD_" +
                       std::to_string(transform.tex_coord) +
                       ", which the primitive lacks: its texture at (0, 0) everywhere");
  const size_t vertices = d.model.accessors[size_t(position)].count;
  const auto attribute_count = [&](int a) {
    return a < 0 || d.model.accessors[size_t(a)].count >= vertices;
  };
  if (!attribute_count(uv) || !attribute_count(color)) {
    what = "TEXCOORD_" + std::to_string(transform.tex_coord) +
           " or COLOR_0 has fewer elements than POSITION";
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
      !add_corner_uvs(d, uv, transform, triangles, soup, what)) {
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
  for (const PlacedNode& n : nodes) {
    if (d.model.nodes[size_t(n.node)].mesh < 0)
      continue;
    // As a scene places it (gltf_scene.cpp): a mirror would turn the mesh inside out, a zero
    // scale flatten it.
    if (!(glm::determinant(glm::dmat3(n.world)) > 0.0)) {
      error = d.file + ": nodes[" + std::to_string(n.node) +
              "]: a mirroring or singular transform (gfield needs positive scales)";
      return false;
    }
    out.emplace_back(d.model.nodes[size_t(n.node)].mesh, n.world);
  }
  for (size_t m = 0; out.empty() && m < d.model.meshes.size(); ++m)
    out.emplace_back(int(m), glm::dmat4(1.0));
  return true;
}

}  // namespace

std::string gltf_mesh_part(int index) {
  return std::string("#") + std::to_string(index);
}

bool read_gltf_mesh(const GltfDocument& d, const std::string& part, TriangleMesh& mesh,
                    MeshAppearance* appearance, bool texture_pixels,
                    std::vector<std::string>& warnings, std::string& error, MeshLoadStats* stats) {
  std::vector<std::pair<int, glm::dmat4>> placed;
  if (!placements(d, part, placed, error))
    return false;
  GltfSoup soup;
  for (const auto& [m, world] : placed) {
    for (size_t p = 0; p < d.model.meshes[size_t(m)].primitives.size(); ++p) {
      std::string what;
      if (!add_primitive(d, m, p, world, soup, warnings, what)) {
        error = d.file + ": " + where(m, p) + what;
        return false;
      }
    }
  }
  if (soup.mesh.triangles.empty()) {
    error = d.file + ": no triangles" + (part.empty() ? "" : " in mesh " + part);
    return false;
  }
  if (appearance != nullptr && !gltf_appearance(d, soup.any_uv, soup.any_color, soup.any_material,
                                                texture_pixels, soup.appearance, warnings, error))
    return false;
  if (appearance != nullptr)
    *appearance = std::move(soup.appearance);
  mesh = std::move(soup.mesh);
  if (stats)
    *stats = MeshLoadStats{soup.polygons, 0};
  return true;
}

bool load_gltf_mesh(const MeshSource& source, TriangleMesh& mesh, MeshAppearance* appearance,
                    std::vector<std::string>& warnings, std::string& error, MeshLoadStats* stats) {
  GltfDocument d;
  return load_gltf_document(source.file, source.outside_paths, d, error) &&
         read_gltf_mesh(d, source.part, mesh, appearance, source.texture_pixels, warnings, error,
                        stats);
}

}  // namespace gfield
