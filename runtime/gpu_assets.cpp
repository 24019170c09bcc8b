#include "runtime/gpu_assets.hpp"
#include "geometry/outward_normals.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtx/norm.hpp>

namespace gfield {

std::vector<unsigned> geometry_image_triangles(const GeometryImage& image) {
  const int n = image.size;
  std::vector<unsigned> indices;
  const auto covered = [&](int i, int j) {
    return image.coverage[texel_index(image, i, j)] > 0.5f;
  };
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      if (!covered(i, j) || !covered(i + 1, j) || !covered(i, j + 1) || !covered(i + 1, j + 1))
        continue;
      const unsigned a = unsigned(texel_index(image, i, j));
      const unsigned b = unsigned(texel_index(image, i + 1, j));
      const unsigned c = unsigned(texel_index(image, i, j + 1));
      const unsigned d = unsigned(texel_index(image, i + 1, j + 1));
      const float ad = glm::distance2(image.position[a], image.position[d]);
      const float bc = glm::distance2(image.position[b], image.position[c]);
      if (ad <= bc) {
        indices.insert(indices.end(), {a, b, d, a, d, c});
      } else {
        indices.insert(indices.end(), {a, b, c, b, d, c});
      }
    }
  }
  return indices;
}

std::vector<glm::vec3> angle_weighted_normals(const TriangleMesh& mesh) {
  const std::vector<glm::dvec3> outward = outward_vertex_normals(mesh);
  std::vector<glm::vec3> normals(outward.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  for (size_t v = 0; v < outward.size(); ++v) {
    if (outward[v] != glm::dvec3(0.0)) {
      normals[v] = glm::vec3(outward[v]);
    }
  }
  return normals;
}

GpuAssets::~GpuAssets() {
  release();
}

void GpuAssets::release() {
  for (const GpuAsset& asset : assets_)
    if (asset.vertex_array != 0)
      glDeleteVertexArrays(1, &asset.vertex_array);
  if (!buffers_.empty())
    glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
  for (GLuint* texture : {&positions_, &normals_, &fields_}) {
    if (*texture != 0)
      glDeleteTextures(1, texture);
    *texture = 0;
  }
  assets_.clear();
  buffers_.clear();
  texture_bytes_ = 0;
}

bool GpuAssets::upload(const std::vector<const GeometryImage*>& images,
                       const std::vector<const GeometryField*>& fields, std::string& error,
                       const std::vector<const ParameterizedMesh*>& meshes) {
  release();
  GLint max_size = 0, max_layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  const int count = int(images.size());
  if (count == 0)
    return true;
  if (count > max_layers) {
    error = std::to_string(count) + " assets exceed GL_MAX_ARRAY_TEXTURE_LAYERS";
    return false;
  }
  int image_side = 1, field_side_max = 1;
  for (int k = 0; k < count; ++k) {
    image_side = std::max(image_side, images[size_t(k)]->size);
    if (const GeometryField* field = fields[size_t(k)]) {
      const Box &a = field->box, &b = images[size_t(k)]->box;
      const float tolerance = 1e-5f * diagonal(b);
      if (glm::any(glm::greaterThan(glm::abs(a.min - b.min), glm::vec3(tolerance))) ||
          glm::any(glm::greaterThan(glm::abs(a.max - b.max), glm::vec3(tolerance)))) {
        error = field->source + ": the geometry field's box does not match its geometry image's";
        return false;
      }
      field_side_max = std::max(field_side_max, field_side(*field));
    }
  }
  if (image_side > max_size || field_side_max > max_size) {
    error = "a " + std::to_string(std::max(image_side, field_side_max)) +
            "^2 texture exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(max_size);
    return false;
  }
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &positions_);
  glTextureStorage3D(positions_, 1, GL_RGBA32F, image_side, image_side, count);
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &normals_);
  glTextureStorage3D(normals_, 1, GL_RGBA32F, image_side, image_side, count);
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &fields_);
  glTextureStorage3D(fields_, 1, GL_RG32F, field_side_max, field_side_max, count);
  texture_bytes_ = size_t(image_side) * size_t(image_side) * size_t(count) * 32 +
                   size_t(field_side_max) * size_t(field_side_max) * size_t(count) * 8;
  for (GLuint texture : {positions_, normals_, fields_}) {
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (int k = 0; k < count; ++k) {
    const GeometryImage& image = *images[size_t(k)];
    const int n = image.size;
    std::vector<glm::vec4> position(size_t(n) * size_t(n)), normal(position.size());
    for (size_t t = 0; t < position.size(); ++t) {
      position[t] = glm::vec4(image.position[t], image.coverage[t]);
      normal[t] = glm::vec4(image.normal[t], 0.0f);
    }
    glTextureSubImage3D(positions_, 0, 0, 0, k, n, n, 1, GL_RGBA, GL_FLOAT, position.data());
    glTextureSubImage3D(normals_, 0, 0, 0, k, n, n, 1, GL_RGBA, GL_FLOAT, normal.data());
    GpuAsset asset;
    asset.layer = k;
    asset.image_size = n;
    asset.box = image.box;
    if (const GeometryField* field = fields[size_t(k)]) {
      const int side = field_side(*field);
      glTextureSubImage3D(fields_, 0, 0, 0, k, side, side, 1, GL_RG, GL_FLOAT, field->uv.data());
      asset.samples_per_side = field->samples_per_side;
    }
    // Mesh for rasterisation: position, normal, uv per vertex (per corner when the mesh has
    // corner uvs: a vertex on a chart seam has one uv on each side).
    std::vector<float> vertices;
    std::vector<unsigned> indices;
    const ParameterizedMesh* pm = size_t(k) < meshes.size() ? meshes[size_t(k)] : nullptr;
    if (pm != nullptr) {
      const TriangleMesh& mesh = pm->mesh;
      const std::vector<glm::vec3> normals = angle_weighted_normals(mesh);
      const bool corners = pm->corner_uv.size() == 3 * mesh.triangles.size();
      const auto add_vertex = [&](int v, glm::vec2 uv) {
        const glm::vec3 p(mesh.positions[size_t(v)]);
        const glm::vec3& n = normals[size_t(v)];
        vertices.insert(vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y});
      };
      if (corners) {
        for (size_t f = 0; f < mesh.triangles.size(); ++f) {
          for (int c = 0; c < 3; ++c) {
            add_vertex(mesh.triangles[f][c], pm->corner_uv[3 * f + size_t(c)]);
            indices.push_back(unsigned(3 * f + size_t(c)));
          }
        }
      } else {
        for (size_t v = 0; v < mesh.positions.size(); ++v)
          add_vertex(int(v), glm::vec2(0.0f));
        for (const glm::ivec3& f : mesh.triangles)
          indices.insert(indices.end(), {unsigned(f.x), unsigned(f.y), unsigned(f.z)});
      }
    } else {
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const size_t t = texel_index(image, i, j);
          vertices.insert(vertices.end(),
                          {image.position[t].x, image.position[t].y, image.position[t].z,
                           image.normal[t].x, image.normal[t].y, image.normal[t].z,
                           (float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n)});
        }
      }
      indices = geometry_image_triangles(image);
    }
    GLuint buffers[2] = {0, 0};
    glCreateBuffers(2, buffers);
    buffers_.insert(buffers_.end(), buffers, buffers + 2);
    glNamedBufferStorage(buffers[0], GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(),
                         0);
    glNamedBufferStorage(buffers[1], GLsizeiptr(std::max<size_t>(indices.size(), 1) * 4),
                         indices.empty() ? nullptr : indices.data(), 0);
    glCreateVertexArrays(1, &asset.vertex_array);
    glVertexArrayVertexBuffer(asset.vertex_array, 0, buffers[0], 0, 8 * sizeof(float));
    glVertexArrayElementBuffer(asset.vertex_array, buffers[1]);
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
      glEnableVertexArrayAttrib(asset.vertex_array, attribute);
      glVertexArrayAttribFormat(asset.vertex_array, attribute, attribute == 2 ? 2 : 3, GL_FLOAT,
                                GL_FALSE, attribute * 3 * sizeof(float));
      glVertexArrayAttribBinding(asset.vertex_array, attribute, 0);
    }
    asset.index_count = GLsizei(indices.size());
    assets_.push_back(asset);
  }
  return true;
}

}  // namespace gfield
