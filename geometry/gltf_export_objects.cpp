#include "geometry/gltf_export_objects.hpp"

#include <cmath>
#include <filesystem>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/shape_tessellation.hpp"
#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// Texels per side of a baked colour chart (its whole [0, 1]^2) and of a baked checker's period
/// (2 x 2 squares, repeated by KHR_texture_transform: 256 texels a square, so that the bilinear
/// lookup blurs a square's edge by 1/256 of it, however many squares the surface has).
constexpr int kBakedTextureSize = 1024;
constexpr int kCheckerPeriodTexels = 512;

std::string key_text(const json& key) {
  return key.dump(-1, ' ', false, json::error_handler_t::replace);
}

/// The glTF material of a surface of object material `m` with base colour `base` and texture
/// `texture` (a textureInfo; null: none); `thickness` is a dielectric's KHR_materials_volume
/// thicknessFactor.
json material_json(const Material& m, glm::vec3 base, const json& texture, double thickness) {
  json pbr = {{"metallicFactor", 0.0}, {"roughnessFactor", 1.0}};
  json out = {{"doubleSided", true}};
  if (m.type == MaterialType::kMirror) {
    pbr = {{"metallicFactor", 1.0}, {"roughnessFactor", 0.0}};
    base = m.color;
  } else if (m.type == MaterialType::kDielectric) {
    pbr["roughnessFactor"] = 0.0;
    base = glm::vec3(1.0f);
    out["doubleSided"] = false;  // a volume's boundary (KHR_materials_volume)
    json volume = {{"thicknessFactor", thickness}};
    if (glm::any(glm::greaterThan(m.absorption, glm::vec3(0.0f))))
      volume.update(
          {{"attenuationDistance", 1.0}, {"attenuationColor", vec(glm::exp(-m.absorption))}});
    out["extensions"] = {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                         {"KHR_materials_ior", {{"ior", m.ior}}},
                         {"KHR_materials_volume", volume}};
  }
  pbr["baseColorFactor"] = {base.x, base.y, base.z, 1.0};
  if (!texture.is_null())
    pbr["baseColorTexture"] = texture;
  out["pbrMetallicRoughness"] = pbr;
  return out;
}

/// The vertices of a mesh: one per (vertex, texture coordinate) pair, or per face corner when
/// `flat`; the indices of the faces of each material (-1: none) into them.
struct ExportedMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec4> colors;
  std::map<int, std::vector<std::uint32_t>> faces;  ///< by material
};

ExportedMesh exported_mesh(const TriangleMesh& mesh, const MeshAppearance& a, bool flat) {
  ExportedMesh out;
  std::map<std::tuple<int, float, float, size_t>, std::uint32_t> index;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    std::vector<std::uint32_t>& faces =
        out.faces[a.face_material.empty() ? -1 : a.face_material[f]];
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.triangles[f][c];
      const glm::vec2 uv = a.corner_uv.empty() ? glm::vec2(0.0f) : a.corner_uv[3 * f + size_t(c)];
      const auto [it, added] = index.emplace(std::make_tuple(v, uv.x, uv.y, flat ? f : 0),
                                             std::uint32_t(out.positions.size()));
      if (added) {
        out.positions.push_back(glm::vec3(mesh.positions[size_t(v)]));
        out.uvs.emplace_back(uv.x, 1.0f - uv.y);  // glTF: v down
        if (!a.vertex_color.empty())
          out.colors.emplace_back(a.vertex_color[size_t(v)], 1.0f);
      }
      faces.push_back(it->second);
    }
  }
  return out;
}

/// The smallest side of the box of `positions`.
double smallest_side(const std::vector<glm::vec3>& positions) {
  glm::vec3 lo(gpu::GF_FAR), hi(-gpu::GF_FAR);
  for (const glm::vec3& p : positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 side = hi - lo;
  return double(std::min(side.x, std::min(side.y, side.z)));
}

/// Accessors of an exported mesh's vertices: POSITION (with min, max), TEXCOORD_0, COLOR_0.
json vertex_attributes(GlbBuilder& b, const ExportedMesh& m, bool textured) {
  json attributes;
  attributes["POSITION"] = b.add_accessor(m.positions, "VEC3", kArrayBuffer);
  glm::vec3 lo(gpu::GF_FAR), hi(-gpu::GF_FAR);
  for (const glm::vec3& p : m.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  b.doc["accessors"][attributes["POSITION"].get<size_t>()]["min"] = vec(lo);
  b.doc["accessors"][attributes["POSITION"].get<size_t>()]["max"] = vec(hi);
  if (textured)
    attributes["TEXCOORD_0"] = b.add_accessor(m.uvs, "VEC2", kArrayBuffer);
  if (!m.colors.empty())
    attributes["COLOR_0"] = b.add_accessor(m.colors, "VEC4", kArrayBuffer);
  return attributes;
}

/// Material `m`'s procedural texture baked, as a textureInfo (shared by the objects of one
/// texture); null with `error` when it does not encode. A checker is one period of 2 x 2 squares
/// that KHR_texture_transform repeats: gfield's uv (u, v) reads checker(u * su, v * sv), so glTF's
/// (u, 1 - v) is scaled by (su / 2, sv / 2) and offset by (0, 1 - sv / 2) modulo 1.
json baked_texture(GlbBuilder& b, const Material& m, GltfExportCache& cache, std::string& error) {
  const bool checker = m.texture == TextureType::kChecker;
  const std::string key =
      key_text({"baked", int(m.texture), vec(m.checker_colors[0]), vec(m.checker_colors[1]),
                m.checker_scale.x, m.checker_scale.y});
  json info = {{"index", -1}};
  if (checker) {
    const double su = m.checker_scale.x, sv = m.checker_scale.y;
    info["extensions"]["KHR_texture_transform"] = {
        {"scale", {0.5 * su, 0.5 * sv}},
        {"offset", {0.0, 1.0 - 0.5 * sv - std::floor(1.0 - 0.5 * sv)}}};
  }
  if (const auto found = cache.textures.find(key); found != cache.textures.end()) {
    info["index"] = found->second;
    return info;
  }
  const int size = checker ? kCheckerPeriodTexels : kBakedTextureSize;
  Image image(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const glm::vec2 uv((float(x) + 0.5f) / float(size), 1.0f - (float(y) + 0.5f) / float(size));
      image.at(x, y) = checker ? m.checker_colors[size_t((int(2.0f * uv.x) + int(2.0f * uv.y)) & 1)]
                               : texture_albedo(m, uv);
    }
  }
  std::string png;
  if (!encode_png(image, png)) {
    error = "cannot encode a baked texture as PNG";
    return nullptr;
  }
  info["index"] = cache.textures[key] = b.add_png_texture(png);
  return info;
}

/// `base` within glTF's [0, 1]; false with `error` otherwise.
bool base_color_fits(glm::vec3 base, std::string& error) {
  if (glm::all(glm::lessThanEqual(base, glm::vec3(1.0f))))
    return true;
  error = "a colour above 1 (glTF's baseColorFactor ends at 1)";
  return false;
}

/// One primitive of `faces` with `attributes` and a material of its own.
json primitive(GlbBuilder& b, const json& attributes, const std::vector<std::uint32_t>& faces,
               const json& material) {
  return {{"attributes", attributes},
          {"indices", b.add_accessor(faces, "SCALAR", kElementArrayBuffer)},
          {"material", b.push("materials", material)},
          {"mode", 4}};
}

/// The glTF texture of texture `t` of mesh asset `mesh` (read as `a`); -1 with `error`.
int mesh_texture(GlbBuilder& b, int mesh, const MeshAppearance& a, int t, GltfExportCache& cache,
                 std::string& error) {
  const std::string key = key_text({"mesh", mesh, t});
  if (const auto found = cache.textures.find(key); found != cache.textures.end())
    return found->second;
  std::string png;
  if (!encode_png(a.textures[size_t(t)].image, png)) {
    error = "cannot encode its texture as PNG";
    return -1;
  }
  return cache.textures[key] = b.add_png_texture(png);
}

/// The glTF mesh of a mesh object: its file's triangles, one primitive per material.
bool export_mesh(GlbBuilder& b, const Scene& scene, const SceneObject& o, GltfExportCache& cache,
                 int& mesh_index, std::string& error) {
  const MeshAsset& asset = scene.meshes[size_t(o.shape.mesh)];
  const Material& material = o.material;
  const bool own = material.texture == TextureType::kMesh, flat = !o.shape.smooth_normals;
  TriangleMesh mesh;
  MeshAppearance a;
  std::vector<std::string> warnings;
  if (!load_mesh(MeshSource{asset.file, asset.part, asset.outside_paths}, mesh, &a, warnings,
                 error))
    return false;
  const ExportedMesh m = exported_mesh(mesh, own ? a : MeshAppearance{}, flat);
  json& attributes = cache.attributes[key_text({o.shape.mesh, own, flat})];
  if (attributes.is_null())
    attributes = vertex_attributes(b, m, own && !a.corner_uv.empty());
  json primitives = json::array();
  for (const auto& [mi, faces] : m.faces) {
    glm::vec3 base = material.color;
    json texture;
    if (mi >= 0) {
      base *= a.materials[size_t(mi)].factor;
      const int t = a.materials[size_t(mi)].texture;
      const int index = t >= 0 ? mesh_texture(b, o.shape.mesh, a, t, cache, error) : -1;
      if (t >= 0 && index < 0)
        return false;
      if (index >= 0)
        texture = {{"index", index}};
    }
    if (!base_color_fits(base, error))
      return false;
    primitives.push_back(primitive(
        b, attributes, faces, material_json(material, base, texture, smallest_side(m.positions))));
  }
  mesh_index = b.push("meshes",
                      {{"name", fs::path(asset.file).stem().string()}, {"primitives", primitives}});
  return true;
}

/// The glTF mesh of a quad (two triangles) or a tessellated shape, its procedural texture baked.
bool export_shape(GlbBuilder& b, const SceneObject& o, int segments, GltfExportCache& cache,
                  int& mesh_index, std::string& error) {
  ExportedMesh m;
  if (o.shape.type == ShapeType::kQuad) {
    const glm::vec2 h(0.5f * o.shape.size.x, 0.5f * o.shape.size.y);
    m.positions = {{-h.x, -h.y, 0.0f}, {h.x, -h.y, 0.0f}, {h.x, h.y, 0.0f}, {-h.x, h.y, 0.0f}};
    m.uvs = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    m.faces[0] = {0, 1, 2, 0, 2, 3};
  } else {
    const TessellatedShape t = tessellate_shape(o.shape, segments);
    MeshAppearance a;
    a.corner_uv = t.corner_uv;
    m = exported_mesh(t.mesh, a, false);
  }
  const bool baked =
      o.material.type == MaterialType::kDiffuse && o.material.texture != TextureType::kNone;
  const json texture = baked ? baked_texture(b, o.material, cache, error) : json();
  const glm::vec3 base = baked ? glm::vec3(1.0f) : o.material.color;
  if ((baked && texture.is_null()) || !base_color_fits(base, error))
    return false;
  const json attributes = vertex_attributes(b, m, baked);
  const json material = material_json(o.material, base, texture, smallest_side(m.positions));
  mesh_index = b.push(
      "meshes",
      {{"name", o.name},
       {"primitives", json::array({primitive(b, attributes, m.faces.begin()->second, material)})}});
  return true;
}

}  // namespace

bool export_object_mesh(GlbBuilder& b, const Scene& scene, const SceneObject& o, int segments,
                        GltfExportCache& cache, int& mesh_index, std::string& error) {
  // Instances of one mesh file with one material share a glTF mesh (named after the file);
  // a shape's glTF mesh is named after its object.
  const Material& m = o.material;
  const bool named = o.shape.type != ShapeType::kMesh;
  const std::string key =
      key_text({int(o.shape.type), o.shape.mesh, o.shape.smooth_normals, o.shape.radius,
                o.shape.height, vec(o.shape.size), o.shape.thickness, int(m.type), int(m.texture),
                vec(m.color), vec(m.checker_colors[0]), vec(m.checker_colors[1]), m.checker_scale.x,
                m.checker_scale.y, m.ior, vec(m.absorption), named ? o.name : ""});
  if (const auto found = cache.meshes.find(key); found != cache.meshes.end()) {
    mesh_index = found->second;
    return true;
  }
  const bool ok = o.shape.type == ShapeType::kMesh
                      ? export_mesh(b, scene, o, cache, mesh_index, error)
                      : export_shape(b, o, segments, cache, mesh_index, error);
  if (ok)
    cache.meshes[key] = mesh_index;
  return ok;
}

}  // namespace gfield
