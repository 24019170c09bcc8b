#include "runtime/gpu_assets.hpp"

#include <algorithm>
#include <filesystem>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/outward_normals.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/gpu_contract.hpp"
#include "gfield/gpu_storage.hpp"
#include "gfield/published_build.hpp"
#include "runtime/image_atlas.hpp"
#include "runtime/image_grid.hpp"

namespace gfield {
namespace {

/// A 2D-array texture of `layers` layers of width x height texels of `format`, nearest
/// filtering.
void make_array(GlTexture& texture, GLenum format, int width, int height, int layers) {
  texture.make(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(texture.id(), 1, format, width, height, layers);
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

/// False with "OWNER: problem" when `count` layers of side^2 exceed the GL limits.
bool fits_gl_limits(int side, int count, const std::string& owner, std::string& error) {
  GLint max_size = 0, max_layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (count > max_layers) {
    error = owner + ": " + std::to_string(count) + " layers exceed GL_MAX_ARRAY_TEXTURE_LAYERS";
    return false;
  }
  if (side > max_size) {
    error = owner + ": a " + std::to_string(side) + "^2 texture exceeds GL_MAX_TEXTURE_SIZE " +
            std::to_string(max_size);
    return false;
  }
  return true;
}

/// The mesh file's triangles, one vertex per corner, with the reference tracer's shading normals
/// (angle-weighted, outwards; +Z where a vertex has none), the mesh's own texture coordinates and
/// base colour (material colour x vertex colour; its texture's layer: `first_layer` + the
/// material's texture).
void source_vertices(const TriangleMesh& mesh, const MeshAppearance& appearance, int first_layer,
                     std::vector<GpuVertex>& vertices, std::vector<unsigned>& indices) {
  const std::vector<glm::dvec3> normals = outward_vertex_normals(mesh);
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const int m = appearance.face_material.empty() ? -1 : appearance.face_material[f];
    const BaseColorMaterial* material = m >= 0 ? &appearance.materials[size_t(m)] : nullptr;
    for (int c = 0; c < 3; ++c) {
      const size_t v = size_t(mesh.triangles[f][c]);
      const glm::vec3 n =
          normals[v] != glm::dvec3(0.0) ? glm::vec3(normals[v]) : glm::vec3(0, 0, 1);
      GpuVertex vertex{
          glm::vec3(mesh.positions[v]), n,
          appearance.corner_uv.empty() ? glm::vec2(0.0f) : appearance.corner_uv[3 * f + size_t(c)]};
      glm::vec3 color =
          appearance.vertex_color.empty() ? glm::vec3(1.0f) : appearance.vertex_color[v];
      if (material != nullptr) {
        color *= material->factor;
        vertex.base.a = material->texture >= 0 ? float(first_layer + material->texture) : -1.0f;
      }
      vertex.base = glm::vec4(color, vertex.base.a);
      indices.push_back(unsigned(vertices.size()));
      vertices.push_back(vertex);
    }
  }
}

/// `image` at width x height (bilinear, repeating: texture_lookup), rows from v = 0 up (the
/// layout of a GL texture whose t is v).
std::vector<glm::vec4> texture_layer(const Image& image, int width, int height) {
  std::vector<glm::vec4> texels(size_t(width) * size_t(height));
  for (int row = 0; row < height; ++row) {
    for (int x = 0; x < width; ++x) {
      const size_t t = size_t(row) * size_t(width) + size_t(x);
      const bool same = image.width == width && image.height == height;
      const glm::vec3 c =
          same ? image.at(x, height - 1 - row)
               : texture_lookup(image, glm::vec2((float(x) + 0.5f) / float(width),
                                                 (float(row) + 0.5f) / float(height)));
      texels[t] = glm::vec4(c, 1.0f);
    }
  }
  return texels;
}

/// One vertex per corner (a vertex on a chart seam has one uv on each side of it).
void parameterized_vertices(const ParameterizedMesh& pm, std::vector<GpuVertex>& vertices,
                            std::vector<unsigned>& indices) {
  const std::vector<glm::dvec3> normals = outward_vertex_normals(pm.mesh);
  for (size_t f = 0; f < pm.mesh.triangles.size(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const size_t v = size_t(pm.mesh.triangles[f][c]);
      const glm::vec3 n =
          normals[v] != glm::dvec3(0.0) ? glm::vec3(normals[v]) : glm::vec3(0, 0, 1);
      indices.push_back(unsigned(vertices.size()));
      vertices.push_back({glm::vec3(pm.mesh.positions[v]), n, pm.corner_uv[3 * f + size_t(c)]});
    }
  }
}

/// The geometry image's grid: a vertex per texel centre.
void grid_vertices(const GeometryImage& image, std::vector<GpuVertex>& vertices,
                   std::vector<unsigned>& indices) {
  const int n = image.size;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const size_t t = texel_index(image, i, j);
      vertices.push_back({image.position[t],
                          image.normal[t],
                          {(float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n)}});
    }
  }
  indices = geometry_image_triangles(image);
}

}  // namespace

void GpuMesh::upload(const std::vector<GpuVertex>& vertex_data,
                     const std::vector<unsigned>& index_data) {
  vertices.make();
  glNamedBufferStorage(vertices.id(),
                       GLsizeiptr(std::max<size_t>(1, vertex_data.size()) * sizeof(GpuVertex)),
                       vertex_data.empty() ? nullptr : vertex_data.data(), 0);
  indices.make();
  glNamedBufferStorage(indices.id(),
                       GLsizeiptr(std::max<size_t>(1, index_data.size()) * sizeof(unsigned)),
                       index_data.empty() ? nullptr : index_data.data(), 0);
  vertex_array.make();
  glVertexArrayVertexBuffer(vertex_array.id(), 0, vertices.id(), 0, sizeof(GpuVertex));
  glVertexArrayElementBuffer(vertex_array.id(), indices.id());
  const GLuint offsets[4] = {offsetof(GpuVertex, position), offsetof(GpuVertex, normal),
                             offsetof(GpuVertex, uv), offsetof(GpuVertex, base)};
  const GLint sizes[4] = {3, 3, 2, 4};
  for (GLuint attribute = 0; attribute < 4; ++attribute) {
    glEnableVertexArrayAttrib(vertex_array.id(), attribute);
    glVertexArrayAttribFormat(vertex_array.id(), attribute, sizes[attribute], GL_FLOAT, GL_FALSE,
                              offsets[attribute]);
    glVertexArrayAttribBinding(vertex_array.id(), attribute, 0);
  }
  index_count = GLsizei(index_data.size());
  vertex_count = GLsizei(vertex_data.size());
}

void GpuMesh::draw() const {
  if (index_count == 0)
    return;
  glBindVertexArray(vertex_array.id());
  glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
}

std::string missing_asset_message(const MeshAsset& mesh, const std::string& scene_file,
                                  const char* what) {
  const std::string stem = std::filesystem::path(mesh.file).stem().string();
  return mesh.file + ": no " + what + " (expected " + stem + ".gimage.exr and " + stem +
         ".gfield.exr beside the mesh, in the --assets folder or named by \"gimage\"/\"gfield\" "
         "in " +
         scene_file + "; make them with: gfield build " + mesh.file + " -o DIR/" + stem + ")";
}

namespace {

/// Each mesh's published build, as its geometry image's name names the asset.
std::vector<std::string> published_builds(const Scene& scene) {
  std::vector<std::string> builds;
  for (const MeshAsset& mesh : scene.meshes) {
    const std::string name = asset_name_of(mesh.geometry_image);
    builds.push_back(name.empty() ? "" : published_build(name));
  }
  return builds;
}

}  // namespace

bool GpuAssets::require(const Scene& scene, AssetNeeds needs, std::string& error) {
  for (int attempt = 0;; ++attempt) {
    if (!loaded_.images && !loaded_.fields && !loaded_.parameterized_meshes)
      read_builds_ = published_builds(scene);
    if (require_once(scene, needs, error))
      return true;
    if (attempt == 2 || published_builds(scene) == read_builds_)
      return false;
    loaded_.images = loaded_.fields = loaded_.parameterized_meshes = false;
  }
}

bool GpuAssets::require_once(const Scene& scene, AssetNeeds needs, std::string& error) {
  if (assets_.size() != scene.meshes.size())
    assets_ = std::vector<GpuAsset>(scene.meshes.size());
  needs.images = needs.images || needs.fields || needs.parameterized_meshes;
  needs.source_meshes = needs.source_meshes || needs.bvhs;
  const bool fields_loaded = loaded_.fields && field_bits_ == needs.field_bits;
  const bool optional = needs.optional_fields;
  if (!((!needs.images || loaded_.images || load_images(scene, optional, error)) &&
        (!needs.fields || fields_loaded || load_fields(scene, needs.field_bits, optional, error)) &&
        (!needs.source_meshes || loaded_.source_meshes || load_source_meshes(scene, error)) &&
        (!needs.parameterized_meshes || loaded_.parameterized_meshes ||
         load_parameterized_meshes(scene, error)) &&
        check_complete(scene, needs, error)))
    return false;
  if (needs.bvhs && !loaded_.bvhs) {
    bvhs_.build(assets_);
    loaded_.bvhs = true;
  }
  return true;
}

bool GpuAssets::check_complete(const Scene& scene, const AssetNeeds& needs,
                               std::string& error) const {
  for (size_t m = 0; m < assets_.size() && !needs.optional_fields; ++m) {
    if (needs.images && assets_[m].layer < 0) {
      error = missing_asset_message(scene.meshes[m], scene.filename, "geometry image");
      return false;
    }
    if (needs.fields && assets_[m].samples_per_side == 0) {
      error = missing_asset_message(scene.meshes[m], scene.filename, "geometry field");
      return false;
    }
  }
  return true;
}

bool GpuAssets::upload(const std::vector<const GeometryImage*>& images,
                       const std::vector<const GeometryField*>& fields, int field_bits,
                       std::string& error) {
  assets_ = std::vector<GpuAsset>(images.size());
  images_.clear();
  for (const GeometryImage* image : images)
    images_.push_back(*image);
  loaded_ = AssetNeeds{};
  if (!upload_images("in-memory assets", error))
    return false;
  std::vector<int> samples(images.size(), 0);
  for (size_t m = 0; m < std::min(fields.size(), images.size()); ++m) {
    samples[m] = fields[m] != nullptr ? fields[m]->samples_per_side : 0;
  }
  if (!make_field_array(samples, field_bits, "in-memory assets", error))
    return false;
  for (size_t m = 0; m < std::min(fields.size(), images.size()); ++m) {
    if (fields[m] != nullptr)
      upload_field(m, *fields[m]);
  }
  upload_field_lines();
  loaded_.fields = true;
  return true;
}

bool GpuAssets::load_images(const Scene& scene, bool optional, std::string& error) {
  images_.assign(scene.meshes.size(), GeometryImage{});
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const MeshAsset& mesh = scene.meshes[m];
    if (mesh.geometry_image.empty() && optional)
      continue;  // no image (size 0): traced by its BVH
    if (mesh.geometry_image.empty()) {
      error = missing_asset_message(mesh, scene.filename, "geometry image");
      return false;
    }
    if (!load_geometry_image(mesh.geometry_image, images_[m], error))
      return false;
  }
  return upload_images(scene.filename, error);
}

bool GpuAssets::upload_images(const std::string& owner, std::string& error) {
  int side = 1;
  std::vector<int> sizes;
  for (const GeometryImage& image : images_) {
    side = std::max(side, image.size);
    sizes.push_back(std::max(1, image.size));  // a missing image (size 0) holds a 1^2 slot
  }
  int layers = 0;
  const std::vector<AtlasSlot> slots = pack_image_atlas(sizes, side, layers);
  const int count = std::max(1, layers);
  if (!fits_gl_limits(side, count, owner, error))
    return false;
  make_array(positions_, GL_RGBA32F, side, side, count);
  make_array(normals_, GL_RGBA32F, side, side, count);
  make_array(albedo_, GL_RGBA16F, side, side, count);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (size_t m = 0; m < images_.size(); ++m) {
    const GeometryImage& image = images_[m];
    assets_[m].layer = -1;
    if (image.size == 0)
      continue;
    std::vector<glm::vec4> position(image.position.size()), normal(image.position.size());
    std::vector<glm::vec4> albedo(image.position.size(), glm::vec4(1.0f));
    for (size_t t = 0; t < position.size(); ++t) {
      position[t] = glm::vec4(image.position[t], image.coverage[t]);
      normal[t] = glm::vec4(image.normal[t], 0.0f);
      if (!image.albedo.empty())
        albedo[t] = glm::vec4(image.albedo[t], 1.0f);
    }
    const int n = image.size;
    const AtlasSlot& s = slots[m];
    glTextureSubImage3D(positions_.id(), 0, s.x, s.y, s.layer, n, n, 1, GL_RGBA, GL_FLOAT,
                        position.data());
    glTextureSubImage3D(normals_.id(), 0, s.x, s.y, s.layer, n, n, 1, GL_RGBA, GL_FLOAT,
                        normal.data());
    glTextureSubImage3D(albedo_.id(), 0, s.x, s.y, s.layer, n, n, 1, GL_RGBA, GL_FLOAT,
                        albedo.data());
    assets_[m].layer = s.layer;
    assets_[m].image_origin = glm::ivec2(s.x, s.y);
    assets_[m].image_size = n;
    assets_[m].box = image.box;
    assets_[m].albedo = !image.albedo.empty();
    assets_[m].ray_offset = image.ray_offset;
    assets_[m].image_bytes = geometry_image_gpu_bytes(n);
  }
  image_texture_bytes_ = geometry_image_gpu_bytes(side) * size_t(count);
  ++texture_uploads_;
  loaded_.images = true;
  return true;
}

bool GpuAssets::load_fields(const Scene& scene, int bits, bool optional, std::string& error) {
  // Headers first (the array's size), then one field at a time: their float tables (80 MB each at
  // N = 24) need not all be in memory at once. With `optional`, a mesh without a field or image
  // gets none.
  std::vector<int> samples(scene.meshes.size(), 0);
  const auto skipped = [&](size_t m) {
    return optional && (scene.meshes[m].geometry_field.empty() || assets_[m].layer < 0);
  };
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const MeshAsset& mesh = scene.meshes[m];
    ExrAssetHeader header;
    if (skipped(m))
      continue;
    if (mesh.geometry_field.empty()) {
      error = missing_asset_message(mesh, scene.filename, "geometry field");
      return false;
    }
    if (!load_asset_header(mesh.geometry_field, header, error))
      return false;
    samples[m] = header.samples_per_side;
  }
  if (!make_field_array(samples, bits, scene.filename, error))
    return false;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const MeshAsset& mesh = scene.meshes[m];
    GeometryField field;
    if (skipped(m))
      continue;
    if (!load_geometry_field(mesh.geometry_field, field, error))
      return false;
    FieldLookup lookup;
    if (!make_field_lookup(field, images_[m], lookup, error)) {
      error = mesh.geometry_field + ": does not match " + mesh.geometry_image + " (" + error + ")";
      return false;
    }
    if (field.samples_per_side != samples[m]) {
      error = mesh.geometry_field + ": changed while it was read";
      return false;
    }
    upload_field(m, field);
  }
  upload_field_lines();
  return true;
}

bool GpuAssets::make_field_array(const std::vector<int>& samples, int bits,
                                 const std::string& owner, std::string& error) {
  int width = 1, height = 1, count = 0;
  for (size_t m = 0; m < samples.size(); ++m) {
    const int n = samples[m];
    width = std::max(width, 5 * n * n);
    height = std::max(height, 6 * n * n);
    assets_[m].field_layer = n > 0 ? count++ : 0;
    assets_[m].field_layers = 0;
    assets_[m].samples_per_side = 0;
    assets_[m].field_bytes = 0;
  }
  count = std::max(1, count);
  if (!fits_gl_limits(std::max(width, height), count, owner, error))
    return false;
  const GLenum format = bits == 8 ? GL_RG8 : bits == 16 ? GL_RG16 : GL_RG32F;
  make_array(fields_, format, width, height, count);
  field_layer_bytes_ = size_t(width) * size_t(height) * 2 * size_t(bits / 8);
  field_texture_bytes_ = field_layer_bytes_ * size_t(count);
  field_words_.clear();
  field_bits_ = bits;
  ++texture_uploads_;
  loaded_.fields = false;  // until every field is uploaded
  return true;
}

void GpuAssets::upload_field(size_t m, const GeometryField& field) {
  const GLenum type = field_bits_ == 8    ? GL_UNSIGNED_BYTE
                      : field_bits_ == 16 ? GL_UNSIGNED_SHORT
                                          : GL_FLOAT;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::vector<uint8_t> texels = field_nearest_texels(field, field_bits_);
  glTextureSubImage3D(fields_.id(), 0, 0, 0, assets_[m].field_layer, field_columns(field),
                      field_side(field), 1, GL_RG, type, texels.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  GpuAsset& a = assets_[m];
  a.samples_per_side = field.samples_per_side;
  a.field_layers = field.layers;
  a.field_lines = int(field_words_.size());
  field_words_.insert(field_words_.end(), field.lines.begin(), field.lines.end());
  a.field_interior = int(field_words_.size());
  const std::vector<uint32_t> interior = field_interior_words(field, field_bits_);
  field_words_.insert(field_words_.end(), interior.begin(), interior.end());
  a.field_bytes = field_layer_bytes_ + (field_words_.size() - size_t(a.field_lines)) * 4;
}

void GpuAssets::upload_field_lines() {
  field_lines_.make();
  const size_t bytes = std::max<size_t>(1, field_words_.size()) * sizeof(uint32_t);
  glNamedBufferStorage(field_lines_.id(), GLsizeiptr(bytes),
                       field_words_.empty() ? nullptr : field_words_.data(), 0);
  field_texture_bytes_ += field_words_.size() * sizeof(uint32_t);
  std::vector<uint32_t>().swap(field_words_);
  loaded_.fields = true;
}

bool GpuAssets::load_source_meshes(const Scene& scene, std::string& error) {
  std::vector<MeshAppearance> appearances(scene.meshes.size());
  std::vector<const Image*> textures;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    TriangleMesh mesh;
    std::vector<std::string> warnings;  // the tools print them when they read the scene
    const MeshAsset& asset = scene.meshes[m];
    if (!load_mesh(MeshSource{asset.file, asset.part, asset.outside_paths}, mesh, &appearances[m],
                   warnings, error))
      return false;
    std::vector<GpuVertex> vertices;
    std::vector<unsigned> indices;
    source_vertices(mesh, appearances[m], int(textures.size()), vertices, indices);
    for (const MeshTexture& texture : appearances[m].textures)
      textures.push_back(&texture.image);
    assets_[m].source.upload(vertices, indices);
    Box bounds{glm::vec3(gpu::GF_FAR), glm::vec3(-gpu::GF_FAR)};
    for (const GpuVertex& v : vertices) {
      bounds.min = glm::min(bounds.min, v.position);
      bounds.max = glm::max(bounds.max, v.position);
    }
    assets_[m].mesh_bounds = bounds;
    if (assets_[m].layer < 0)  // no geometry image: the box is the mesh's bounds
      assets_[m].box = bounds;
  }
  if (!upload_mesh_textures(textures, scene.filename, error))
    return false;
  loaded_.source_meshes = true;
  return true;
}

bool GpuAssets::upload_mesh_textures(const std::vector<const Image*>& textures,
                                     const std::string& owner, std::string& error) {
  int width = 1, height = 1;
  for (const Image* image : textures) {
    width = std::max(width, image->width);
    height = std::max(height, image->height);
  }
  const int count = std::max(1, int(textures.size()));
  if (!fits_gl_limits(std::max(width, height), count, owner, error))
    return false;
  mesh_textures_.make(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(mesh_textures_.id(), 1, GL_RGBA16F, width, height, count);
  glTextureParameteri(mesh_textures_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(mesh_textures_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(mesh_textures_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(mesh_textures_.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (size_t k = 0; k < textures.size(); ++k) {
    const std::vector<glm::vec4> texels = texture_layer(*textures[k], width, height);
    glTextureSubImage3D(mesh_textures_.id(), 0, 0, 0, GLint(k), width, height, 1, GL_RGBA, GL_FLOAT,
                        texels.data());
  }
  mesh_texture_bytes_ = size_t(width) * size_t(height) * size_t(count) * 8;  // RGBA16F
  return true;
}

bool GpuAssets::load_parameterized_meshes(const Scene& scene, std::string& error) {
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    std::vector<GpuVertex> vertices;
    std::vector<unsigned> indices;
    const std::string path = parameterized_mesh_path(scene.meshes[m].geometry_image);
    if (std::filesystem::exists(path)) {
      ParameterizedMesh pm;
      if (!load_parameterized_mesh_of(images_[m], scene.meshes[m].geometry_image, pm, error))
        return false;
      parameterized_vertices(pm, vertices, indices);
    } else {
      grid_vertices(images_[m], vertices, indices);
    }
    assets_[m].parameterized.upload(vertices, indices);
  }
  loaded_.parameterized_meshes = true;
  return true;
}

}  // namespace gfield
