#include "runtime/gpu_scene.hpp"

#include <algorithm>
#include <cmath>

#include "gfield/environment.hpp"
#include "gfield/scene.hpp"

namespace gfield {
namespace {

/// std430 mirror of GpuObject in shaders/lib/scene.glsl.
struct GpuObject {
  glm::mat4 to_world;
  glm::mat4 to_object;
  glm::vec4 color;       ///< rgb albedo or tint, w = index of refraction
  glm::vec4 absorption;  ///< rgb Beer-Lambert coefficients, w = diagonal of the world bounds
  glm::vec4 checker0;    ///< rgb, w = checker scale u
  glm::vec4 checker1;    ///< rgb, w = checker scale v
  glm::vec4 shape;       ///< radius, height, thickness
  glm::vec4 size;        ///< xyz size of quads, boxes, slabs
  glm::vec4 box_min;     ///< object_local_bounds (meshes: the box of the field's unit cube)
  glm::vec4 box_max;
  glm::ivec4 kind;   ///< shape type, material type, texture type
  glm::ivec4 asset;  ///< meshes: layer, samples per side N, geometry-image size n
};
static_assert(sizeof(GpuObject) == 288);

/// std430 mirror of GpuLight in shaders/lib/scene.glsl.
struct GpuLight {
  glm::vec4 direction;  ///< xyz direction of a directional light, w = 1 for a point light
  glm::vec4 position;
  glm::vec4 color;  ///< rgb colour * intensity
};

}  // namespace

glm::vec3 shape_half_extent(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::kSphere:
      return glm::vec3(shape.radius);
    case ShapeType::kQuad:
      return glm::vec3(0.5f * shape.size.x, 0.5f * shape.size.y, 0.0f);
    case ShapeType::kBox:
      return 0.5f * shape.size;
    case ShapeType::kSlab:
      return 0.5f * glm::vec3(shape.size.x, shape.size.y, shape.thickness);
    case ShapeType::kCylinder:
    case ShapeType::kHollowCylinder:
      return glm::vec3(shape.radius, 0.5f * shape.height, shape.radius);
    case ShapeType::kMesh:
      break;
  }
  return glm::vec3(0.0f);
}

void object_local_bounds(const Scene& scene, const GpuAssets& assets, int object, glm::vec3& lo,
                         glm::vec3& hi) {
  const SceneObject& o = scene.objects[size_t(object)];
  if (o.shape.type == ShapeType::kMesh) {
    const GpuAsset& asset = assets.assets()[size_t(o.shape.mesh)];
    lo = asset.box.min;
    hi = asset.box.max;
  } else {
    hi = shape_half_extent(o.shape);
    lo = -hi;
  }
}

void object_world_bounds(const Scene& scene, const GpuAssets& assets, int object, glm::vec3& lo,
                         glm::vec3& hi) {
  glm::vec3 olo, ohi;
  object_local_bounds(scene, assets, object, olo, ohi);
  const glm::mat4 to_world(object_to_world(scene.objects[size_t(object)].transform));
  lo = glm::vec3(3.0e38f);
  hi = glm::vec3(-3.0e38f);
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner((c & 1) ? ohi.x : olo.x, (c & 2) ? ohi.y : olo.y,
                           (c & 4) ? ohi.z : olo.z);
    const glm::vec3 w(to_world * glm::vec4(corner, 1.0f));
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  }
}

void create_proxy_cube(GLuint& buffer, GLuint& vertex_array) {
  std::vector<float> v;
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {-1.0f, 1.0f}) {
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      const float corners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
      for (const auto& c : corners) {
        glm::vec3 p(0.0f), n(0.0f);
        p[axis] = side;
        p[a1] = c[0];
        p[a2] = c[1];
        n[axis] = side;
        v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z, 0.0f, 0.0f});
      }
    }
  }
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, GLsizeiptr(v.size() * sizeof(float)), v.data(), 0);
  glCreateVertexArrays(1, &vertex_array);
  glVertexArrayVertexBuffer(vertex_array, 0, buffer, 0, 8 * sizeof(float));
  for (GLuint attribute = 0; attribute < 3; ++attribute) {
    glEnableVertexArrayAttrib(vertex_array, attribute);
    glVertexArrayAttribFormat(vertex_array, attribute, attribute == 2 ? 2 : 3, GL_FLOAT, GL_FALSE,
                              attribute * 3 * sizeof(float));
    glVertexArrayAttribBinding(vertex_array, attribute, 0);
  }
}

void set_camera_ray_uniforms(const ShaderProgram& program, const Camera& camera, int width,
                             int height, glm::vec2 jitter) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_half = std::tan(glm::radians(camera.fov_degrees) * 0.5f);
  const float aspect = float(width) / float(height);
  glUniform3fv(program.uniform("u_camera_position"), 1, &camera.position.x);
  glUniform3fv(program.uniform("u_camera_forward"), 1, &forward.x);
  glUniform3fv(program.uniform("u_camera_right"), 1, &right.x);
  glUniform3fv(program.uniform("u_camera_up"), 1, &up.x);
  glUniform2f(program.uniform("u_tan_half"), tan_half * aspect, tan_half);
  glUniform2f(program.uniform("u_image_size"), float(width), float(height));
  glUniform2f(program.uniform("u_jitter"), jitter.x, jitter.y);
}

void set_environment_uniforms(const ShaderProgram& program, const EnvironmentDesc& environment) {
  glUniform1i(program.uniform("u_env_type"), int(environment.type));
  glUniform3fv(program.uniform("u_env_color"), 1, &environment.color.x);
  glUniform1f(program.uniform("u_env_intensity"), environment.intensity);
}

float upload_scene_buffers(const Scene& scene, const GpuAssets& assets, GLuint& objects_buffer,
                           GLuint& lights_buffer) {
  std::vector<GpuObject> objects;
  glm::vec3 lo(scene.camera.position), hi(scene.camera.position);
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    GpuObject g{};
    const glm::dmat4 to_world = object_to_world(o.transform);
    g.to_world = glm::mat4(to_world);
    g.to_object = glm::mat4(glm::inverse(to_world));
    g.color = glm::vec4(o.material.color, o.material.ior);
    glm::vec3 olo, ohi;
    object_world_bounds(scene, assets, int(k), olo, ohi);
    lo = glm::min(lo, olo);
    hi = glm::max(hi, ohi);
    g.absorption = glm::vec4(o.material.absorption, glm::length(ohi - olo));
    g.checker0 = glm::vec4(o.material.checker_colors[0], o.material.checker_scale.x);
    g.checker1 = glm::vec4(o.material.checker_colors[1], o.material.checker_scale.y);
    g.shape = glm::vec4(o.shape.radius, o.shape.height, o.shape.thickness, 0.0f);
    g.size = glm::vec4(o.shape.size, 0.0f);
    g.kind = glm::ivec4(int(o.shape.type), int(o.material.type), int(o.material.texture), 0);
    glm::vec3 local_lo, local_hi;
    object_local_bounds(scene, assets, int(k), local_lo, local_hi);
    g.box_min = glm::vec4(local_lo, 0.0f);
    g.box_max = glm::vec4(local_hi, 0.0f);
    if (o.shape.type == ShapeType::kMesh) {
      const GpuAsset& asset = assets.assets()[size_t(o.shape.mesh)];
      g.asset = glm::ivec4(asset.layer, asset.samples_per_side, asset.image_size, 0);
    }
    objects.push_back(g);
  }
  std::vector<GpuLight> lights;
  for (const Light& l : scene.lights)
    lights.push_back({glm::vec4(l.direction, l.type == LightType::kPoint ? 1.0f : 0.0f),
                      glm::vec4(l.position, 1.0f), glm::vec4(l.color * l.intensity, 0.0f)});
  // Buffers are re-created: sizes change when objects are added in the viewer.
  for (GLuint* buffer : {&objects_buffer, &lights_buffer}) {
    if (*buffer != 0)
      glDeleteBuffers(1, buffer);
    glCreateBuffers(1, buffer);
  }
  glNamedBufferData(objects_buffer,
                    GLsizeiptr(std::max<size_t>(1, objects.size()) * sizeof(GpuObject)),
                    objects.empty() ? nullptr : objects.data(), GL_DYNAMIC_DRAW);
  glNamedBufferData(lights_buffer,
                    GLsizeiptr(std::max<size_t>(1, lights.size()) * sizeof(GpuLight)),
                    lights.empty() ? nullptr : lights.data(), GL_DYNAMIC_DRAW);
  return std::max(1e-3f, glm::length(hi - lo));
}

bool upload_environment_texture(const EnvironmentDesc& desc, GLuint& texture, std::string& error) {
  Environment environment;
  if (!load_environment(desc, environment, error))
    return false;
  std::vector<const Image*> layers;
  if (desc.type == EnvironmentType::kEquirect)
    layers.push_back(&environment.equirect);
  if (desc.type == EnvironmentType::kCube)
    for (const Image& face : environment.faces)
      layers.push_back(&face);
  const int width = layers.empty() ? 1 : layers[0]->width;
  const int height = layers.empty() ? 1 : layers[0]->height;
  if (texture != 0)
    glDeleteTextures(1, &texture);
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &texture);
  glTextureStorage3D(texture, 1, GL_RGBA32F, width, height,
                     GLsizei(std::max<size_t>(1, layers.size())));
  for (size_t k = 0; k < layers.size(); ++k) {
    std::vector<glm::vec4> pixels;
    pixels.reserve(layers[k]->pixels.size());
    for (const glm::vec3& p : layers[k]->pixels)
      pixels.emplace_back(p, 1.0f);
    glTextureSubImage3D(texture, 0, 0, 0, GLint(k), width, height, 1, GL_RGBA, GL_FLOAT,
                        pixels.data());
  }
  return true;
}

}  // namespace gfield
