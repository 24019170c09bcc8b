#pragma once
// Geometry images and geometry fields on the GPU. All assets of a scene share three texture
// arrays so that a shader can reach any object's data with a layer index:
//   - positions: GL_TEXTURE_2D_ARRAY RGBA32F, layer = asset, texel (i, j) = P (mesh coordinates)
//     in xyz and coverage A in w; an n x n image fills the corner [0,n)^2 of the layer;
//   - normals:   GL_TEXTURE_2D_ARRAY RGBA32F (unit normals in xyz);
//   - fields:    GL_TEXTURE_2D_ARRAY RG32F, texel (exit, entry) = stored uv of the pair; a
//     (6N^2)^2 table fills the corner of its layer (3D textures stop at 2048 on Mesa, a 2D array
//     layer reaches 16384).
// Shaders read them with texelFetch only (bilinear weights are computed in the shader, as the
// CPU does, instead of the texture unit's fixed-point filtering). Each asset also has a triangle
// mesh for rasterisation when one is given (the scene's mesh file, or the parameterised mesh
// NAME.gimage.obj, whose corner uvs reach the asset's per-texel maps), else the geometry image's
// grid. Instances share one asset.

#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "gfield/geometry_field.hpp"
#include "gfield/geometry_image.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/parameterized_mesh.hpp"

namespace gfield {

/// Where one asset lives on the GPU.
struct GpuAsset {
  int layer = 0;             ///< layer in the three arrays
  int image_size = 0;        ///< n of the geometry image
  int samples_per_side = 0;  ///< N of the field (0: no field)
  Box box;                   ///< mesh-coordinate box of the unit cube
  GLuint vertex_array = 0;   ///< attributes 0 = position, 1 = normal, 2 = geometry-image uv
  GLsizei index_count = 0;   ///< triangles * 3
};

class GpuAssets {
 public:
  GpuAssets() = default;
  ~GpuAssets();
  GpuAssets(const GpuAssets&) = delete;
  GpuAssets& operator=(const GpuAssets&) = delete;

  /// Uploads the image and field of every asset (fields[i] may be null: no field) and its
  /// rasterisation mesh (meshes[i] may be null or meshes empty: the geometry image grid; a mesh
  /// without corner uvs gets uv 0). False with an error when an image and its field do not
  /// belong together (box) or a size exceeds the GL limits.
  bool upload(const std::vector<const GeometryImage*>& images,
              const std::vector<const GeometryField*>& fields, std::string& error,
              const std::vector<const ParameterizedMesh*>& meshes = {});

  const std::vector<GpuAsset>& assets() const { return assets_; }
  GLuint positions() const { return positions_; }
  GLuint normals() const { return normals_; }
  GLuint fields() const { return fields_; }
  /// Bytes of texture memory held.
  size_t texture_bytes() const { return texture_bytes_; }

 private:
  void release();
  std::vector<GpuAsset> assets_;
  std::vector<GLuint> buffers_;
  GLuint positions_ = 0;
  GLuint normals_ = 0;
  GLuint fields_ = 0;
  size_t texture_bytes_ = 0;
};

/// Angle-weighted vertex normals of `mesh`, oriented outwards by the signed volume (as the
/// reference tracer computes its shading normals).
std::vector<glm::vec3> angle_weighted_normals(const TriangleMesh& mesh);

/// Grid triangles of a geometry image: two per quad of texel centres whose 4 corners are covered
/// (A > 0.5), as indices j * n + i. Quads are split along the shorter diagonal.
std::vector<unsigned> geometry_image_triangles(const GeometryImage& image);

}  // namespace gfield
