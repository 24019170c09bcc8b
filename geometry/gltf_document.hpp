#pragma once
// A glTF 2.0 file (.gltf with its buffers and images, or .glb) read by Debian's tinygltf after
// gfield has checked what tinygltf trusts: the .glb container (header, chunk lengths against the
// file), the JSON (strict, at most kMaxJsonDepth deep, arrays of at most kMaxGltfElements), every
// index into another array (scene, nodes, meshes, accessors, buffer views, buffers, materials,
// textures, images, samplers, cameras, lights, skins, animations), the node hierarchy (a forest:
// one parent at most, no cycle), the buffer and image URIs (data: URIs, or relative paths inside
// the glTF file's folder unless outside paths are allowed: confined_path.hpp), the external
// buffers (present, of their byteLength), then every buffer view within its buffer and every
// accessor within its view. Internal to geometry's glTF code (gltf_mesh.cpp, gltf_scene.cpp);
// tiny_gltf.h is included here only.

#include <set>
#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "gfield/confined_path.hpp"

namespace gfield {

struct GltfDocument {
  std::string file;       ///< the glTF file
  tinygltf::Model model;  ///< every index checked (see above)
  nlohmann::json json;    ///< the document's JSON: extensions and extras are read from it
  OutsidePaths outside_paths = OutsidePaths::kRefused;  ///< as it was read
  /// Accessors decoded from KHR_draco_mesh_compression: their declared min and max bound Draco's
  /// quantisation grid (gltf-pipeline writes them so), not the decoded values; not checked.
  std::set<int> draco_accessors;
};

/// Reads and checks `filename`, its URIs confined to its folder unless `outside` is kAllowed.
/// False with a one-line error "FILE: problem" (JSON problems: "FILE:LINE:COLUMN: path:
/// problem"; for a .glb, lines count in its JSON chunk).
bool load_gltf_document(const std::string& filename, OutsidePaths outside, GltfDocument& document,
                        std::string& error);

/// The bounds `lo`, `hi` of the points `xyz` (x, y, z of each; lo > hi when there are none).
void position_bounds(const std::vector<float>& xyz, glm::dvec3& lo, glm::dvec3& hi);

/// Checks the min and max that accessor `index` declares against `lo` and `hi`, the bounds of
/// its values computed from the data (normalised for a normalized accessor, whose min and max
/// hold the stored integers): a warning "FILE: /accessors/I/max: declares ..., the data reach
/// ...; gfield uses the data's bounds" when they differ by more than rounding.
void check_declared_bounds(const GltfDocument& document, int index, const glm::dvec3& lo,
                           const glm::dvec3& hi, std::vector<std::string>& warnings);

/// The `components` floats of each of accessor `index`'s elements (normalised integers mapped to
/// [0, 1] or [-1, 1], plain integers converted), `count * components` values. An accessor without
/// a buffer view reads as zeros.
std::vector<float> read_accessor_floats(const GltfDocument& document, int index);
/// The elements of scalar integer accessor `index` (indices).
std::vector<std::int64_t> read_accessor_integers(const GltfDocument& document, int index);
/// Components per element of an accessor's type (SCALAR 1 ... MAT4 16).
int accessor_components(const tinygltf::Accessor& accessor);

/// The local matrix of node `node` (its matrix, or T * R * S).
glm::dmat4 node_matrix(const tinygltf::Node& node);

/// The nodes of the document's scene (its "scene", else scene 0; without scenes, every node
/// without a parent), each with its world matrix, parents before children. glTF is +Y up,
/// right-handed, like gfield's world.
struct PlacedNode {
  int node = -1;
  glm::dmat4 world{1.0};
};
/// False with "FILE: problem" when the scene places more than kMaxGltfElements nodes.
bool scene_nodes(const GltfDocument& document, std::vector<PlacedNode>& placed, std::string& error);

struct MeshAppearance;

/// Materials and textures of `appearance` (whose corner uvs, vertex colours and face materials,
/// indices of glTF materials, the primitives filled): one BaseColorMaterial per glTF material
/// (baseColorFactor's rgb, and for the materials the faces use, their baseColorTexture's image),
/// the images used decoded (each checked against the texture budget first: check_texture_budget;
/// with `pixels` false, only their headers read), embedded bytes that are no image: an error
/// "FILE: images[I]: problem"; a missing external image: mid-grey and a warning. Attributes no
/// primitive had (`any_*` false) are dropped.
bool gltf_appearance(const GltfDocument& document, bool any_uv, bool any_color, bool any_material,
                     bool pixels, MeshAppearance& appearance, std::vector<std::string>& warnings,
                     std::string& error);

/// True when the document's extensionsUsed names extension `name`.
bool uses_extension(const GltfDocument& document, const char* name);

/// `"KEY"` of JSON object `object` at path `keys` (e.g. {"extensions",
/// "KHR_materials_ior", "ior"}), or null.
const nlohmann::json* json_at(const nlohmann::json& object,
                              std::initializer_list<const char*> keys);

/// The number of `object` at path `keys` (`fallback` when absent) in `value`; false, with `what`
/// ("KEY.KEY must be in RANGE (is VALUE)") appended, when it lies outside [lo, hi] (`range`: the
/// interval as the docs write it, e.g. "[0, 1e6]").
bool number_at(const nlohmann::json& object, std::initializer_list<const char*> keys,
               double fallback, double lo, double hi, const char* range, double& value,
               std::string& what);

}  // namespace gfield
