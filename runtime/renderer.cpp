#include "runtime/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gfield/exr_io.hpp"
#include "geometry/mesh_io.hpp"
#include "runtime/gpu_scene.hpp"
#include "runtime/supersample.hpp"

namespace gfield {
namespace {

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

Renderer::Renderer() = default;

Renderer::~Renderer() {
  release_gbuffer();
  for (GLuint* buffer : {&objects_buffer_, &lights_buffer_, &proxy_buffer_})
    if (*buffer != 0)
      glDeleteBuffers(1, buffer);
  if (environment_ != 0)
    glDeleteTextures(1, &environment_);
  for (GLuint* array : {&proxy_vertex_array_, &empty_vertex_array_})
    if (*array != 0)
      glDeleteVertexArrays(1, array);
}

bool Renderer::load(const Scene& scene, const std::filesystem::path& shader_dir,
                    std::string& error) {
  scene_ = scene;
  // Assets: every mesh needs its geometry image and its field, and they must belong together.
  std::vector<GeometryImage> images(scene.meshes.size());
  std::vector<GeometryField> fields(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const MeshAsset& mesh = scene.meshes[m];
    const std::string stem = std::filesystem::path(mesh.file).stem().string();
    if (mesh.geometry_image.empty() || mesh.geometry_field.empty()) {
      error = mesh.file + ": no " +
              std::string(mesh.geometry_image.empty() ? "geometry image" : "geometry field") +
              " (expected " + stem + ".gimage.exr and " + stem +
              ".gfield.exr beside the mesh, in the --assets folder or named by "
              "\"gimage\"/\"gfield\" in " +
              scene.filename + "; make them with: gfield build " + mesh.file + " -o DIR/" + stem +
              ")";
      return false;
    }
    if (!load_geometry_image(mesh.geometry_image, images[m], error))
      return false;
    if (!load_geometry_field(mesh.geometry_field, fields[m], error))
      return false;
    FieldLookup lookup;
    if (!make_field_lookup(fields[m], images[m], lookup, error)) {
      error = mesh.geometry_field + ": does not match " + mesh.geometry_image + " (" + error + ")";
      return false;
    }
  }
  // Rasterisation meshes: the scene's mesh files themselves (as the reference tracer sees them).
  std::vector<ParameterizedMesh> raster(scene.meshes.size());
  std::vector<const GeometryImage*> image_pointers;
  std::vector<const GeometryField*> field_pointers;
  std::vector<const ParameterizedMesh*> mesh_pointers;
  for (size_t m = 0; m < images.size(); ++m) {
    image_pointers.push_back(&images[m]);
    field_pointers.push_back(&fields[m]);
    if (!load_mesh(scene.meshes[m].file, raster[m].mesh, error))
      return false;
    mesh_pointers.push_back(&raster[m]);
  }
  if (!assets_.upload(image_pointers, field_pointers, error, mesh_pointers)) {
    error = scene.filename + ": " + error;
    return false;
  }
  if (!upload_environment_texture(scene_.environment, environment_, error))
    return false;

  create_proxy_cube(proxy_buffer_, proxy_vertex_array_);
  glCreateVertexArrays(1, &empty_vertex_array_);
  glCreateBuffers(1, &objects_buffer_);
  glCreateBuffers(1, &lights_buffer_);
  update_scene();

  if (!gbuffer_program_.build(shader_dir, {"gbuffer.vert", "gbuffer.frag"}, "", error))
    return false;
  if (!trace_program_.build(shader_dir, {"fullscreen.vert", "field_trace.frag"}, "", error))
    return false;
  return true;
}

void Renderer::update_scene() {
  extent_ = upload_scene_buffers(scene_, assets_, objects_buffer_, lights_buffer_);
}

void Renderer::release_gbuffer() {
  if (gbuffer_fbo_ != 0)
    glDeleteFramebuffers(1, &gbuffer_fbo_);
  if (gbuffer_textures_[0] != 0)
    glDeleteTextures(3, gbuffer_textures_);
  if (gbuffer_depth_ != 0)
    glDeleteRenderbuffers(1, &gbuffer_depth_);
  gbuffer_fbo_ = gbuffer_depth_ = 0;
  gbuffer_textures_[0] = gbuffer_textures_[1] = gbuffer_textures_[2] = 0;
  gbuffer_width_ = gbuffer_height_ = 0;
}

bool Renderer::ensure_gbuffer(int width, int height) {
  if (width == gbuffer_width_ && height == gbuffer_height_ && gbuffer_fbo_ != 0)
    return true;
  release_gbuffer();
  glCreateTextures(GL_TEXTURE_2D, 3, gbuffer_textures_);
  glCreateFramebuffers(1, &gbuffer_fbo_);
  for (int k = 0; k < 3; ++k) {
    glTextureStorage2D(gbuffer_textures_[k], 1, GL_RGBA32F, width, height);
    glNamedFramebufferTexture(gbuffer_fbo_, GLenum(GL_COLOR_ATTACHMENT0 + k), gbuffer_textures_[k],
                              0);
  }
  glCreateRenderbuffers(1, &gbuffer_depth_);
  glNamedRenderbufferStorage(gbuffer_depth_, GL_DEPTH_COMPONENT32F, width, height);
  glNamedFramebufferRenderbuffer(gbuffer_fbo_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 gbuffer_depth_);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(gbuffer_fbo_, 3, buffers);
  gbuffer_width_ = width;
  gbuffer_height_ = height;
  return glCheckNamedFramebufferStatus(gbuffer_fbo_, GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

void Renderer::render(const Camera& camera, const RenderSettings& settings, Framebuffer& target,
                      glm::vec2 jitter, FrameStats* stats) {
  const int width = target.width(), height = target.height();
  ensure_gbuffer(width, height);
  const auto start = std::chrono::steady_clock::now();
  const float aspect = float(width) / float(height);
  const float distance_to_target = glm::length(camera.target - camera.position);
  const float far_plane = 4.0f * extent_ + distance_to_target;
  const float near_plane = 1e-4f * far_plane;
  const glm::mat4 view = glm::lookAt(camera.position, camera.target, camera.up);
  glm::mat4 projection =
      glm::perspective(glm::radians(camera.fov_degrees), aspect, near_plane, far_plane);
  projection = jittered_projection(projection, jitter, width, height);
  const glm::mat4 view_projection = projection * view;

  // Pass 1: G-buffer of first hits.
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_fbo_);
  glViewport(0, 0, width, height);
  const float clear_position[4] = {0.0f, 0.0f, 0.0f, -1.0f};
  const float clear_zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, clear_position);
  glClearBufferfv(GL_COLOR, 1, clear_zero);
  glClearBufferfv(GL_COLOR, 2, clear_zero);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const GLuint gp = gbuffer_program_.id();
  glUseProgram(gp);
  glUniformMatrix4fv(gbuffer_program_.uniform("u_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(view_projection));
  glUniform3fv(gbuffer_program_.uniform("u_camera_position"), 1, &camera.position.x);
  for (size_t k = 0; k < scene_.objects.size(); ++k) {
    const SceneObject& o = scene_.objects[k];
    const glm::dmat4 to_world_d = object_to_world(o.transform);
    const glm::mat4 to_world(to_world_d), to_object(glm::inverse(to_world_d));
    glUniformMatrix4fv(gbuffer_program_.uniform("u_to_world"), 1, GL_FALSE,
                       glm::value_ptr(to_world));
    glUniformMatrix4fv(gbuffer_program_.uniform("u_to_object"), 1, GL_FALSE,
                       glm::value_ptr(to_object));
    glUniform1i(gbuffer_program_.uniform("u_object"), int(k));
    glUniform1i(gbuffer_program_.uniform("u_shape"), int(o.shape.type));
    glUniform4f(gbuffer_program_.uniform("u_shape_params"), o.shape.radius, o.shape.height,
                o.shape.thickness, 0.0f);
    glUniform3fv(gbuffer_program_.uniform("u_shape_size"), 1, &o.shape.size.x);
    if (o.shape.type == ShapeType::kMesh) {
      const GpuAsset& asset = assets_.assets()[size_t(o.shape.mesh)];
      glUniform3f(gbuffer_program_.uniform("u_proxy_half"), 1.0f, 1.0f, 1.0f);
      glBindVertexArray(asset.vertex_array);
      glDrawElements(GL_TRIANGLES, asset.index_count, GL_UNSIGNED_INT, nullptr);
    } else {
      // A slightly grown box: the exact shape is found per fragment.
      const glm::vec3 half = shape_half_extent(o.shape) * 1.001f + 1e-5f * extent_;
      glUniform3fv(gbuffer_program_.uniform("u_proxy_half"), 1, &half.x);
      glBindVertexArray(proxy_vertex_array_);
      glDrawArrays(GL_TRIANGLES, 0, 36);
    }
  }
  double gbuffer_ms = 0.0;
  if (stats != nullptr) {
    glFinish();
    gbuffer_ms = elapsed_ms(start);
  }

  // Pass 2: shading and tracing.
  target.bind();
  glDisable(GL_DEPTH_TEST);
  const GLuint tp = trace_program_.id();
  glUseProgram(tp);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, objects_buffer_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, lights_buffer_);
  glBindTextureUnit(0, assets_.positions());
  glBindTextureUnit(1, assets_.normals());
  glBindTextureUnit(2, assets_.fields());
  glBindTextureUnit(5, environment_);
  for (int k = 0; k < 3; ++k)
    glBindTextureUnit(GLuint(6 + k), gbuffer_textures_[k]);
  const auto& u = [&](const char* name) { return trace_program_.uniform(name); };
  glUniform1i(u("u_object_count"), int(scene_.objects.size()));
  glUniform1i(u("u_light_count"), int(scene_.lights.size()));
  glUniform3fv(u("u_ambient"), 1, &scene_.ambient.x);
  glUniform1i(u("u_mode"), int(settings.mode));
  glUniform1i(u("u_self_reflection"), settings.self_reflection ? 1 : 0);
  glUniform1f(u("u_scene_extent"), extent_);
  set_environment_uniforms(trace_program_, scene_.environment);
  set_camera_ray_uniforms(trace_program_, camera, width, height, jitter);
  glUniform1i(u("u_max_depth"), settings.max_depth);
  glUniform1f(u("u_min_weight"), settings.min_weight);
  glUniform1i(u("u_max_rays"), settings.max_rays);
  glBindVertexArray(empty_vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (stats != nullptr) {
    glFinish();
    stats->milliseconds += elapsed_ms(start);
    stats->gbuffer_milliseconds += gbuffer_ms;
    stats->trace_milliseconds += elapsed_ms(start) - gbuffer_ms;
    for (const glm::vec4& h : target.read_hits()) {
      if (h.x >= 0.0f && scene_.objects[size_t(h.x)].material.type != MaterialType::kDiffuse)
        ++stats->traced_pixels;
      stats->secondary_rays += (long long)(h.y);
    }
  }
}

Image Renderer::render_image(int width, int height, const RenderSettings& settings,
                             FrameStats* stats) {
  return render_supersampled(width, height, settings.samples_per_pixel,
                             [&](Framebuffer& target, glm::vec2 jitter) {
                               render(scene_.camera, settings, target, jitter, stats);
                             });
}

bool Renderer::reload_shaders_if_changed(std::string& error) {
  std::string gbuffer_error, trace_error;
  const bool a = gbuffer_program_.reload_if_changed(gbuffer_error);
  const bool b = trace_program_.reload_if_changed(trace_error);
  error = gbuffer_error + trace_error;
  return (a || b) && error.empty();
}

}  // namespace gfield
