#include "runtime/gpu_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "geometry/analytic_primitives.hpp"
#include "gfield/environment.hpp"
#include "gfield/gpu_contract.hpp"
#include "gfield/printable.hpp"
#include "runtime/supersample.hpp"

namespace gfield {
namespace {

/// The cube [-1, 1]^3 (outward normals, uv 0) that rasterises analytic shapes.
void make_proxy_cube(GpuMesh& cube) {
  std::vector<GpuVertex> vertices;
  std::vector<unsigned> indices;
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
        indices.push_back(unsigned(vertices.size()));
        vertices.push_back({p, n, glm::vec2(0.0f)});
      }
    }
  }
  cube.upload(vertices, indices);
}

/// The contract's GpuObject of object k.
gpu::GpuObject gpu_object(const GpuScene& gpu_scene, int k) {
  const SceneObject& o = gpu_scene.scene_object(k);
  gpu::GpuObject g{};
  const glm::dmat4 to_world = object_to_world(o.transform);
  g.to_world = glm::mat4(to_world);
  g.to_object = glm::mat4(glm::inverse(to_world));
  g.color = glm::vec4(o.material.color, o.material.ior);
  glm::vec3 lo, hi;
  gpu_scene.object_world_bounds(k, lo, hi);
  g.absorption = glm::vec4(o.material.absorption, glm::length(hi - lo));
  g.checker0 = glm::vec4(o.material.checker_colors[0], o.material.checker_scale.x);
  g.checker1 = glm::vec4(o.material.checker_colors[1], o.material.checker_scale.y);
  g.shape = glm::vec4(o.shape.radius, o.shape.height, o.shape.thickness, 0.0f);
  g.size = glm::vec4(o.shape.size, 0.0f);
  g.kind = glm::ivec4(int(o.shape.type), int(o.material.type), int(o.material.texture), 0);
  gpu_scene.object_local_bounds(k, lo, hi);
  g.box_min = glm::vec4(lo, 0.0f);
  g.box_max = glm::vec4(hi, 0.0f);
  if (o.shape.type == ShapeType::kMesh) {
    const GpuAsset& asset = gpu_scene.assets().asset(o.shape.mesh);
    g.box_min.w = asset.ray_offset;
    g.asset =
        glm::ivec4(asset.layer, asset.samples_per_side, asset.image_size, asset.albedo ? 1 : 0);
    g.field = glm::ivec4(asset.field_layer, asset.field_lines, asset.field_interior,
                         gpu_scene.assets().field_bits() + 256 * asset.field_layers);
    g.image =
        glm::ivec4(asset.image_origin, asset.bvh_root, gpu_scene.bvh_route(o.shape.mesh) ? 1 : 0);
  }
  return g;
}

/// Replaces `buffer` by one holding `data` (at least one element's worth of bytes).
template <class T>
void fill_buffer(GlBuffer& buffer, const std::vector<T>& data) {
  buffer.make();
  glNamedBufferData(buffer.id(), GLsizeiptr(std::max<size_t>(1, data.size()) * sizeof(T)),
                    data.empty() ? nullptr : data.data(), GL_DYNAMIC_DRAW);
}

}  // namespace

bool GpuScene::load(const Scene& scene, std::string& error) {
  scene_ = scene;
  assets_ = GpuAssets();
  // No assets yet, but one (empty) entry per mesh.
  if (!assets_.require(scene_, AssetNeeds{}, error) ||
      !upload_environment_texture(scene_.environment, environment_, error))
    return false;
  make_proxy_cube(proxy_);
  empty_.make();
  update();
  return true;
}

bool GpuScene::require(const AssetNeeds& needs, std::string& error) {
  if (!assets_.require(scene_, needs, error))
    return false;
  update();
  return true;
}

void GpuScene::set_bvh_routes(std::vector<char> by_bvh) {
  bvh_routes_ = std::move(by_bvh);
  update();
}

void GpuScene::update() {
  std::vector<gpu::GpuObject> objects;
  glm::vec3 lo(scene_.camera.position), hi(scene_.camera.position);
  for (int k = 0; k < int(scene_.objects.size()); ++k) {
    objects.push_back(gpu_object(*this, k));
    glm::vec3 olo, ohi;
    object_world_bounds(k, olo, ohi);
    lo = glm::min(lo, olo);
    hi = glm::max(hi, ohi);
  }
  std::vector<gpu::GpuLight> lights;
  for (const Light& l : scene_.lights)
    lights.push_back({glm::vec4(l.direction, l.type == LightType::kPoint ? 1.0f : 0.0f),
                      glm::vec4(l.position, 1.0f), glm::vec4(l.color * l.intensity, 0.0f)});
  fill_buffer(objects_, objects);
  fill_buffer(lights_, lights);
  extent_ = std::max(1e-3f, glm::length(hi - lo));
}

void GpuScene::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BUFFER_OBJECTS, objects_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BUFFER_LIGHTS, lights_.id());
  glBindTextureUnit(gpu::UNIT_GI_POSITIONS, assets_.positions());
  glBindTextureUnit(gpu::UNIT_GI_NORMALS, assets_.normals());
  glBindTextureUnit(gpu::UNIT_FIELDS, assets_.fields());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BUFFER_FIELD_LINES, assets_.field_lines());
  glBindTextureUnit(gpu::UNIT_GI_ALBEDO, assets_.albedo());
  glBindTextureUnit(gpu::UNIT_MESH_TEXTURES, assets_.mesh_textures());
  glBindTextureUnit(gpu::UNIT_ENVIRONMENT, environment_.id());
  assets_.bvhs().bind();
}

void GpuScene::set_uniforms(const ShaderProgram& program) const {
  const auto u = [&](const char* name) { return program.uniform_if_declared(name); };
  glUniform1i(u("u_object_count"), int(scene_.objects.size()));
  glUniform1i(u("u_light_count"), int(scene_.lights.size()));
  glUniform3fv(u("u_ambient"), 1, &scene_.ambient.x);
  glUniform1f(u("u_scene_extent"), extent_);
  glUniform1i(u("u_env_type"), int(scene_.environment.type));
  glUniform3fv(u("u_env_color"), 1, &scene_.environment.color.x);
  glUniform1f(u("u_env_intensity"), scene_.environment.intensity);
}

GpuScene::ObjectUniforms GpuScene::object_uniforms(int object) const {
  const SceneObject& o = scene_object(object);
  ObjectUniforms u;
  const glm::dmat4 to_world_d = object_to_world(o.transform);
  u.to_world = glm::mat4(to_world_d);
  u.to_object = glm::mat4(glm::inverse(to_world_d));
  u.normal_to_world = glm::mat3(glm::transpose(glm::inverse(glm::dmat3(to_world_d))));
  u.shape = int(o.shape.type);
  u.shape_params = glm::vec4(o.shape.radius, o.shape.height, o.shape.thickness, 0.0f);
  u.shape_size = o.shape.size;
  if (o.shape.type == ShapeType::kMesh) {
    u.mesh = o.shape.mesh;
    u.gi_size = assets_.asset(o.shape.mesh).image_size;
    return u;
  }
  // A slightly grown box: the exact shape is found per fragment.
  glm::dvec3 lo, hi;
  shape_bounds(o.shape, lo, hi);
  u.proxy_half = glm::vec3(hi) * 1.001f + 1e-5f * extent_;
  return u;
}

void GpuScene::set_object_uniforms(const ShaderProgram& program, int object) const {
  const ObjectUniforms o = object_uniforms(object);
  const auto u = [&](const char* name) { return program.uniform_if_declared(name); };
  glUniformMatrix4fv(u("u_to_world"), 1, GL_FALSE, glm::value_ptr(o.to_world));
  glUniformMatrix4fv(u("u_to_object"), 1, GL_FALSE, glm::value_ptr(o.to_object));
  glUniformMatrix3fv(u("u_normal_to_world"), 1, GL_FALSE, glm::value_ptr(o.normal_to_world));
  glUniform1i(u("u_object"), object);
  glUniform1i(u("u_shape"), o.shape);
  glUniform4fv(u("u_shape_params"), 1, &o.shape_params.x);
  glUniform3fv(u("u_shape_size"), 1, &o.shape_size.x);
  glUniform3fv(u("u_proxy_half"), 1, &o.proxy_half.x);
  if (o.mesh >= 0)
    glUniform1i(u("u_gi_size"), o.gi_size);
}

void GpuScene::draw_object(const ShaderProgram& program, int object, RasterMesh raster) const {
  set_object_uniforms(program, object);
  const Shape& shape = scene_object(object).shape;
  if (shape.type != ShapeType::kMesh) {
    proxy_.draw();
    return;
  }
  const GpuAsset& asset = assets_.asset(shape.mesh);
  (raster == RasterMesh::kSource ? asset.source : asset.parameterized).draw();
}

void GpuScene::draw_fullscreen() const {
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GpuScene::object_local_bounds(int object, glm::vec3& lo, glm::vec3& hi) const {
  const SceneObject& o = scene_object(object);
  if (o.shape.type == ShapeType::kMesh) {
    const Box& box = assets_.asset(o.shape.mesh).box;
    lo = box.min;
    hi = box.max;
    return;
  }
  glm::dvec3 dlo, dhi;
  shape_bounds(o.shape, dlo, dhi);
  lo = glm::vec3(dlo);
  hi = glm::vec3(dhi);
}

void GpuScene::object_world_bounds(int object, glm::vec3& lo, glm::vec3& hi) const {
  glm::vec3 olo, ohi;
  object_local_bounds(object, olo, ohi);
  lo = glm::vec3(gpu::GF_FAR);
  hi = glm::vec3(-gpu::GF_FAR);
  grow_world_bounds(glm::mat4(object_to_world(scene_object(object).transform)), olo, ohi, lo, hi);
}

void grow_world_bounds(const glm::mat4& to_world, glm::vec3 box_lo, glm::vec3 box_hi, glm::vec3& lo,
                       glm::vec3& hi) {
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner((c & 1) ? box_hi.x : box_lo.x, (c & 2) ? box_hi.y : box_lo.y,
                           (c & 4) ? box_hi.z : box_lo.z);
    const glm::vec3 w(to_world * glm::vec4(corner, 1.0f));
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  }
}

void set_camera_uniforms(const ShaderProgram& program, const Camera& camera, int width, int height,
                         glm::vec2 jitter) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_half = std::tan(glm::radians(camera.fov_degrees) * 0.5f);
  const float aspect = float(width) / float(height);
  glUniform3fv(program.uniform_if_declared("u_camera_position"), 1, &camera.position.x);
  glUniform3fv(program.uniform_if_declared("u_camera_forward"), 1, &forward.x);
  glUniform3fv(program.uniform_if_declared("u_camera_right"), 1, &right.x);
  glUniform3fv(program.uniform_if_declared("u_camera_up"), 1, &up.x);
  glUniform2f(program.uniform_if_declared("u_tan_half"), tan_half * aspect, tan_half);
  glUniform2f(program.uniform_if_declared("u_image_size"), float(width), float(height));
  glUniform2f(program.uniform_if_declared("u_jitter"), jitter.x, jitter.y);
}

glm::vec2 depth_range(glm::vec3 eye, const GpuScene& scene, float edge_cosine, int skip) {
  const glm::dvec3 p(eye);
  double nearest = std::numeric_limits<double>::max(), farthest = 0.0;
  bool inside = false;
  for (int k = 0; k < int(scene.scene().objects.size()); ++k) {
    if (k == skip)
      continue;
    glm::vec3 lo, hi;
    scene.object_world_bounds(k, lo, hi);
    const glm::dvec3 below = glm::dvec3(lo) - p, above = glm::dvec3(hi) - p;
    const double to_box = glm::length(glm::max(glm::max(below, -above), 0.0));
    farthest = std::max(farthest, glm::length(glm::max(glm::abs(below), glm::abs(above))));
    if (to_box > 0.0)
      nearest = std::min(nearest, to_box);
    else
      inside = true;
  }
  const double far_plane = std::max(1.01 * farthest, 1e-3);
  double near_plane = std::min(0.5 * double(edge_cosine) * nearest, 0.5 * far_plane);
  if (inside || nearest == std::numeric_limits<double>::max())
    near_plane = std::min(near_plane, 1e-4 * far_plane);
  return glm::vec2(float(std::max(near_plane, 1e-7 * far_plane)), float(far_plane));
}

CameraFrustum camera_frustum(const Camera& camera, int width, int height, const GpuScene& scene,
                             glm::vec2 jitter) {
  CameraFrustum f;
  // The view's edge direction: a point at distance d there is at depth d cos(angle).
  const double tan_half = std::tan(glm::radians(double(camera.fov_degrees)) * 0.5);
  const double sides = double(width) / double(height);
  const double edge = std::atan(tan_half * std::sqrt(1.0 + sides * sides));
  const glm::vec2 range = depth_range(camera.position, scene, float(std::cos(edge)));
  f.near_plane = range.x;
  f.far_plane = range.y;
  f.view = glm::lookAt(camera.position, camera.target, camera.up);
  const float aspect = float(width) / float(height);
  f.projection = jittered_projection(
      glm::perspective(glm::radians(camera.fov_degrees), aspect, f.near_plane, f.far_plane), jitter,
      width, height);
  return f;
}

std::string camera_resolution_problem(const Camera& camera) {
  if (camera.fov_degrees >= kMinViewFovDegrees)
    return "";
  return "the camera's field of view of " + float_text(camera.fov_degrees) +
         " degrees is narrower than gfield-view's float rendering resolves (at least " +
         float_text(kMinViewFovDegrees) + " degrees; gfield render takes any)";
}

bool upload_environment_texture(const EnvironmentDesc& desc, GlTexture& texture,
                                std::string& error) {
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
  texture.make(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(texture.id(), 1, GL_RGBA32F, width, height,
                     GLsizei(std::max<size_t>(1, layers.size())));
  for (size_t k = 0; k < layers.size(); ++k) {
    std::vector<glm::vec4> pixels;
    pixels.reserve(layers[k]->pixels.size());
    for (const glm::vec3& p : layers[k]->pixels)
      pixels.emplace_back(p, 1.0f);
    glTextureSubImage3D(texture.id(), 0, 0, 0, GLint(k), width, height, 1, GL_RGBA, GL_FLOAT,
                        pixels.data());
  }
  return true;
}

}  // namespace gfield
