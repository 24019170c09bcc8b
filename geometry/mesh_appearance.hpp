#pragma once
// What a mesh's surface looks like besides its shape: texture coordinates, vertex colours and
// base-colour materials (OBJ vt, `v x y z r g b`, mtllib/usemtl with Kd and map_Kd; PLY u v /
// s t and red green blue; glTF TEXCOORD_0, COLOR_0 and baseColorFactor x baseColorTexture), and
// the albedo they give at a point of a face: material factor x texture at the interpolated uv
// (bilinear, repeating) x interpolated vertex colour, every colour linear RGB. The reference
// tracer shades with base_color_at exactly; the geometry image resamples it (footprint_color);
// the runtime uploads the same textures (runtime/gpu_assets.hpp).
//
// Texture coordinates follow OBJ: (0, 0) is the bottom-left corner of the image, v up (glTF's
// v down is flipped when read). Faces without texture coordinates in a mesh that has some get
// uv (0, 0).

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"
#include "gfield/image.hpp"

namespace gfield {

/// One material's base colour.
struct BaseColorMaterial {
  std::string name;
  glm::vec3 factor{1.0f};  ///< linear RGB (OBJ Kd, glTF baseColorFactor)
  int texture = -1;        ///< index into MeshAppearance::textures; -1: none
};

/// A decoded texture.
struct MeshTexture {
  std::string name;  ///< the image file, or "FILE: image N" for one embedded in a glTF file
  /// Linear RGB, row 0 at the top; 1 x 1 mid-grey when the file is missing. Read without pixels
  /// (MeshSource::texture_pixels false): the width and height its header claims, no pixels.
  Image image;
};

/// Every attribute is optional (empty when the file has none).
struct MeshAppearance {
  std::vector<glm::vec2> corner_uv;     ///< 3F texture coordinates, corner c of face f at 3f + c
  std::vector<glm::vec3> vertex_color;  ///< V linear RGB
  std::vector<int> face_material;       ///< F indices into materials (-1: white, untextured)
  std::vector<BaseColorMaterial> materials;
  std::vector<MeshTexture> textures;
};

/// Linear grey of a texture that cannot be read (0.5).
inline constexpr float kMissingTextureGrey = 0.5f;

/// True when the mesh has a base colour of its own: materials or vertex colours (texture
/// coordinates alone are not one).
bool carries_base_color(const MeshAppearance& appearance);

/// The texture at uv: bilinear between texel centres, repeating in u and v.
glm::vec3 texture_lookup(const Image& image, glm::vec2 uv);

/// The mean of the texture over the parallelogram uv + s du + t dv, s, t in [-1/2, 1/2] (a
/// texel's footprint mapped into the texture): bilinear lookups at the centres of a k x l grid
/// fine enough that neighbours are at most a texel apart (k, l at most 32).
glm::vec3 footprint_lookup(const Image& image, glm::vec2 uv, glm::vec2 du, glm::vec2 dv);

/// Texture coordinates at barycentric weights `w` of face `face` ((0, 0) without any).
glm::vec2 uv_at(const MeshAppearance& appearance, size_t face, glm::dvec3 w);

/// The albedo at barycentric weights `w` (of the face's corners 0, 1, 2) of face `face`:
/// material factor x texture (exact bilinear lookup) x vertex colour; 1 where the mesh has none.
glm::vec3 base_color_at(const TriangleMesh& mesh, const MeshAppearance& appearance, size_t face,
                        glm::dvec3 w);

/// The same with the texture averaged over the footprint of uv derivatives `du`, `dv`
/// (footprint_lookup) instead of looked up at one point.
glm::vec3 footprint_color(const TriangleMesh& mesh, const MeshAppearance& appearance, size_t face,
                          glm::dvec3 w, glm::vec2 du, glm::vec2 dv);

/// Checks that texture `name` of `width` x `height` pixels, decoded, fits in what the textures
/// of `appearance` leave of kMaxMeshTextureBytes: false with "NAME: WxH pixels ... budget ...".
bool check_texture_budget(const std::string& name, int width, int height,
                          const MeshAppearance& appearance, std::string& error);

/// Decodes the texture files `files` into `appearance.textures` (same order), each checked
/// against the texture budget (check_texture_budget) before it is decoded; with `pixels` false
/// reads their headers only (MeshTexture). A missing or unreadable file gives a mid-grey
/// stand-in and a warning "MESH: texture FILE: no such file; mid-grey albedo"; a file that is
/// there but is no image load_image decodes, or is beyond the budget, is an error
/// "MESH: texture FILE: problem".
bool load_texture_files(const std::string& mesh, const std::vector<std::string>& files, bool pixels,
                        MeshAppearance& appearance, std::vector<std::string>& warnings,
                        std::string& error);

}  // namespace gfield
