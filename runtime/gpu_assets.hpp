#pragma once
// The scene's mesh assets on the GPU, loaded on demand (a method asks for what it needs):
//   - geometry images: two GL_TEXTURE_2D_ARRAY RGBA32F textures of layers as large as the largest
//     image, texel (i, j) of an image at GpuAsset::image_origin + (i, j) of GpuAsset::layer = P
//     (mesh coordinates) with coverage A in w, and the unit normal; smaller images share layers
//     (image_atlas.hpp);
//   - geometry fields (compact, gfield/geometry_field.hpp): one GL_TEXTURE_2D_ARRAY of their
//     nearest-hit tables, a layer each, texel (column, entry) = the code of the uv of the hit
//     nearest the entry (RG8 or RG16 normalised integers, or RG32F: the contract's
//     gf_decode_field_texel, gfield/gpu_storage.hpp); a 5N^2 x 6N^2 table fills the corner of
//     its layer (3D textures stop at 2048 on Mesa, a 2D array layer reaches 16384); and one
//     storage buffer of their line tables and interior hits (BUFFER_FIELD_LINES), each field's
//     at GpuAsset::field_lines and field_interior;
//   - geometry-image albedo: GL_TEXTURE_2D_ARRAY RGBA16F, laid out as the images (white for an
//     image without albedo: GpuAsset::albedo);
//   - rasterisation meshes, two per asset: the mesh file as the reference tracer sees it (its
//     shading normals, its own texture coordinates and base colour: the G-buffer's, the
//     image-space methods' and the glass method's first hits), and the parameterised mesh
//     NAME.gimage.obj (the same surface with each corner's geometry-image uv, which reaches the
//     asset's per-texel maps; the image's grid when the file is missing);
//   - the meshes' own textures (mesh_appearance.hpp): one GL_TEXTURE_2D_ARRAY RGBA16F of linear
//     colour, a layer per texture, all at the largest texture's size (smaller ones resampled
//     bilinearly), rows from v = 0 up, GL_LINEAR and GL_REPEAT as the reference tracer's lookup.
// Shaders read the geometry images and fields with texelFetch only (bilinear weights are
// computed in the shader, as the CPU does). Instances share one asset. The texture units are
// the contract's (shaders/lib/contract.glsl: UNIT_GI_POSITIONS, UNIT_GI_NORMALS, UNIT_FIELDS,
// UNIT_GI_ALBEDO, UNIT_MESH_TEXTURES).

#include <cstdint>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "geometry/parameterized_mesh.hpp"
#include "gfield/box.hpp"
#include "gfield/check.hpp"
#include "gfield/geometry_field.hpp"
#include "gfield/geometry_image.hpp"
#include "gfield/scene.hpp"
#include "runtime/gl_object.hpp"
#include "runtime/gpu_bvh.hpp"

namespace gfield {

/// Interleaved vertex of every rasterised mesh: attributes 0 = position, 1 = normal, 2 = uv,
/// 3 = base colour (rgb: the mesh's material colour x vertex colour, linear; a: the layer of its
/// texture in GpuAssets::mesh_textures, -1 none).
struct GpuVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec4 base{1.0f, 1.0f, 1.0f, -1.0f};
};

/// Indexed triangles on the GPU.
struct GpuMesh {
  GlVertexArray vertex_array;
  GlBuffer vertices;
  GlBuffer indices;
  GLsizei index_count = 0;
  GLsizei vertex_count = 0;

  /// Uploads `vertices` and triangle `indices` (three per triangle).
  void upload(const std::vector<GpuVertex>& vertex_data, const std::vector<unsigned>& index_data);
  /// Draws the triangles with the program in use (no-op when empty).
  void draw() const;
};

/// Which assets of the scene's meshes a method needs.
struct AssetNeeds {
  bool images = false;                ///< geometry images
  bool fields = false;                ///< geometry fields (and their images)
  int field_bits = 8;                 ///< bits per uv component of the fields: 8, 16, 32 (float)
  bool source_meshes = false;         ///< the mesh files themselves
  bool parameterized_meshes = false;  ///< NAME.gimage.obj (and the images)
  bool bvhs = false;                  ///< the mesh files' BVHs (and the mesh files): gpu_bvh.hpp
  /// A mesh without a geometry image or field is left without them (GpuAsset::layer -1,
  /// samples_per_side 0) instead of an error: the field method traces it by its BVH.
  bool optional_fields = false;
};

/// Where one asset (one mesh file of the scene) lives on the GPU.
struct GpuAsset {
  int layer = -1;              ///< layer in the texture arrays (-1: no geometry image loaded)
  int image_size = 0;          ///< n of the geometry image
  glm::ivec2 image_origin{0};  ///< texel of its corner in the layer (image_atlas.hpp)
  int samples_per_side = 0;    ///< N of the field (0: no field loaded)
  int field_layer = 0;         ///< its nearest-hit table's layer in the field array
  int field_lines = 0;         ///< first word of its line table in the field lines buffer
  int field_interior = 0;      ///< first word of its interior hits there
  int field_layers = 0;        ///< K, the hits a lookup reads per line
  size_t image_bytes = 0;      ///< GPU bytes of its geometry image (its n x n texels of the arrays)
  size_t field_bytes = 0;      ///< GPU bytes of its field (its layer of the array and its words)
  Box box;  ///< the geometry image's box (mesh coordinates), else the mesh file's bounds
  bool albedo = false;               ///< the geometry image holds albedo (in GpuAssets::albedo)
  float ray_offset = kMinRayOffset;  ///< the geometry image's (box diagonals)
  Box mesh_bounds;                   ///< bounds of the mesh file's vertices (with the source mesh)
  GpuMesh source;  ///< the mesh file, the reference tracer's normals, its own uvs and colours
  GpuMesh parameterized;  ///< NAME.gimage.obj with corner uvs, or the image's grid
  int bvh_root = -1;      ///< its BVH's root in the BVH buffers (-1: none loaded)
  size_t bvh_bytes = 0;   ///< GPU bytes of its BVH (nodes, triangles and their shading)
};

class GpuAssets {
 public:
  /// Loads and uploads, for every mesh of `scene`, what `needs` asks for and is not loaded yet.
  /// False with "FILE: problem" for a missing or damaged asset, a field that does not belong to
  /// its image, or a size beyond the GL limits. Where a read fails after an asset was
  /// republished (since its first file was read), every asset file is read again, of the builds
  /// published now (3 tries): the assets drawn are one build each.
  bool require(const Scene& scene, AssetNeeds needs, std::string& error);
  /// Uploads in-memory geometry images, one asset each, and their fields (fields[i] null or
  /// `fields` empty: none) at `field_bits` bits, replacing what is loaded (tests, tools that make
  /// assets in memory). False when a size exceeds the GL limits.
  bool upload(const std::vector<const GeometryImage*>& images,
              const std::vector<const GeometryField*>& fields, int field_bits, std::string& error);

  const std::vector<GpuAsset>& assets() const { return assets_; }
  /// The asset of the scene's mesh `mesh` (Shape::mesh; GF_DCHECK: loaded).
  const GpuAsset& asset(int mesh) const {
    GF_DCHECK(mesh >= 0 && size_t(mesh) < assets_.size(), "a mesh without a GPU asset");
    return assets_[size_t(mesh)];
  }
  GLuint positions() const { return positions_.id(); }
  GLuint normals() const { return normals_.id(); }
  GLuint fields() const { return fields_.id(); }
  /// The fields' line tables and interior hits (BUFFER_FIELD_LINES).
  GLuint field_lines() const { return field_lines_.id(); }
  GLuint albedo() const { return albedo_.id(); }
  GLuint mesh_textures() const { return mesh_textures_.id(); }
  const GpuBvhs& bvhs() const { return bvhs_; }
  /// Bits per uv component of the fields loaded (8, 16, 32).
  int field_bits() const { return field_bits_; }
  /// Bytes of texture memory held.
  size_t texture_bytes() const {
    return image_texture_bytes_ + field_texture_bytes_ + mesh_texture_bytes_;
  }
  /// How many times texture arrays were filled: a scene edit must not change it.
  int texture_uploads() const { return texture_uploads_; }

 private:
  /// require's one try: what `needs` asks for and is not loaded yet.
  bool require_once(const Scene& scene, AssetNeeds needs, std::string& error);
  bool load_images(const Scene& scene, bool optional, std::string& error);
  bool load_fields(const Scene& scene, int bits, bool optional, std::string& error);
  /// False with the missing-asset message of the first mesh without a geometry image or field.
  bool check_complete(const Scene& scene, const AssetNeeds& needs, std::string& error) const;
  bool upload_images(const std::string& owner, std::string& error);
  /// Allocates the field array for fields of N = `samples` (0: none), one layer each.
  bool make_field_array(const std::vector<int>& samples, int bits, const std::string& owner,
                        std::string& error);
  /// Uploads `field`'s nearest-hit table as the field of asset m (after make_field_array) and
  /// keeps its line table and interior hits for upload_field_lines.
  void upload_field(size_t m, const GeometryField& field);
  /// Uploads the kept line tables and interior hits of every field (BUFFER_FIELD_LINES).
  void upload_field_lines();
  bool load_source_meshes(const Scene& scene, std::string& error);
  bool upload_mesh_textures(const std::vector<const Image*>& textures, const std::string& owner,
                            std::string& error);
  bool load_parameterized_meshes(const Scene& scene, std::string& error);

  std::vector<GpuAsset> assets_;
  std::vector<GeometryImage> images_;  ///< kept for the grid fallback of parameterized meshes
  AssetNeeds loaded_;
  /// Each mesh's published build (published_build.hpp) when its first asset file was read.
  std::vector<std::string> read_builds_;
  GlTexture positions_;
  GlTexture normals_;
  GlTexture fields_;
  GlBuffer field_lines_;
  std::vector<uint32_t> field_words_;  ///< the line tables until upload_field_lines
  size_t field_layer_bytes_ = 0;       ///< bytes of one layer of the field array
  GlTexture albedo_;
  GlTexture mesh_textures_;
  GpuBvhs bvhs_;
  size_t image_texture_bytes_ = 0;  ///< geometry images (positions, normals, albedo)
  size_t field_texture_bytes_ = 0;  ///< the field array
  size_t mesh_texture_bytes_ = 0;   ///< the meshes' own textures
  int texture_uploads_ = 0;
  int field_bits_ = 0;
};

/// The missing-asset message for `mesh`: what was expected where, and the command that makes it.
std::string missing_asset_message(const MeshAsset& mesh, const std::string& scene_file,
                                  const char* what);

}  // namespace gfield
