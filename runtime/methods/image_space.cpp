#include "runtime/methods/image_space.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gfield/exr_io.hpp"
#include "gfield/thickness.hpp"
#include "runtime/gpu_scene.hpp"
#include "runtime/supersample.hpp"

namespace gfield {
namespace {

constexpr float kFar = 1.0e30f;  // IS_FAR of shaders/lib/image_space.glsl

// Texture units of the image-space shaders.
constexpr GLuint kUnitEnvironment = 5;
constexpr GLuint kUnitThickness = 9;
constexpr GLuint kUnitCube = 10;
constexpr GLuint kUnitBack = 11;
constexpr GLuint kUnitFront = 12;
constexpr GLuint kUnitNearby = 13;

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

/// Objects the method shades itself (the rest is drawn by the forward shader).
bool is_special(const SceneObject& o, ImageSpaceMethod method) {
  if (o.material.type == MaterialType::kDielectric)
    return true;
  return o.material.type == MaterialType::kMirror &&
         (method == ImageSpaceMethod::kCubeMap || method == ImageSpaceMethod::kEnvMap);
}

}  // namespace

bool parse_image_space_method(const std::string& name, ImageSpaceMethod& method) {
  for (ImageSpaceMethod m : {ImageSpaceMethod::kCubeMap, ImageSpaceMethod::kEnvMap,
                             ImageSpaceMethod::kWyman2005, ImageSpaceMethod::kDavisWyman}) {
    if (name == image_space_method_name(m)) {
      method = m;
      return true;
    }
  }
  return false;
}

const char* image_space_method_name(ImageSpaceMethod method) {
  switch (method) {
    case ImageSpaceMethod::kCubeMap:
      return "cubemap";
    case ImageSpaceMethod::kEnvMap:
      return "envmap";
    case ImageSpaceMethod::kWyman2005:
      return "wyman2005";
    case ImageSpaceMethod::kDavisWyman:
      return "davis-wyman";
  }
  return "?";
}

/// The camera of one frame as the shaders see it.
struct ImageSpaceRenderer::View {
  glm::vec3 position, forward, right, up;
  glm::vec2 tan_half;
  glm::vec2 near_far;
  glm::vec2 refractor_depths;  ///< eye-depth range of the dielectrics' bounds, within near_far
  glm::vec2 nearby_depths;     ///< of the other objects' bounds
  glm::mat4 view_projection;
  glm::vec2 jitter = glm::vec2(0.0f);  ///< sample offset from the pixel centres (x right, y down)
  int width = 0, height = 0;
};

ImageSpaceRenderer::ImageSpaceRenderer() = default;

ImageSpaceRenderer::~ImageSpaceRenderer() {
  for (ScreenMap* map : {&back_, &front_, &nearby_})
    release_map(*map);
  for (CubeMap& cube : cubes_) {
    if (cube.texture != 0)
      glDeleteTextures(1, &cube.texture);
    if (cube.depth != 0)
      glDeleteRenderbuffers(1, &cube.depth);
  }
  for (GLuint* buffer : {&objects_buffer_, &lights_buffer_, &proxy_buffer_})
    if (*buffer != 0)
      glDeleteBuffers(1, buffer);
  for (GLuint* texture : {&thickness_, &environment_})
    if (*texture != 0)
      glDeleteTextures(1, texture);
  for (GLuint* array : {&proxy_vertex_array_, &empty_vertex_array_})
    if (*array != 0)
      glDeleteVertexArrays(1, array);
  if (cube_framebuffer_ != 0)
    glDeleteFramebuffers(1, &cube_framebuffer_);
}

bool ImageSpaceRenderer::load(const Scene& scene, const std::filesystem::path& shader_dir,
                              std::string& error) {
  scene_ = scene;
  // Geometry images (and thickness maps where present) of every mesh.
  std::vector<GeometryImage> images(scene.meshes.size());
  std::vector<ThicknessMap> thickness(scene.meshes.size());
  thickness_layer_.assign(scene.meshes.size(), -1);
  thickness_missing_.clear();
  int thickness_side = 1;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const MeshAsset& mesh = scene.meshes[m];
    if (mesh.geometry_image.empty()) {
      const std::string stem = std::filesystem::path(mesh.file).stem().string();
      error = mesh.file + ": no geometry image (expected " + stem +
              ".gimage.exr beside the mesh, in the --assets folder or named by \"gimage\" in " +
              scene.filename + "; make it with: gfield build " + mesh.file + " -o DIR/" + stem +
              ")";
      return false;
    }
    if (!load_geometry_image(mesh.geometry_image, images[m], error))
      return false;
    const std::string path = thickness_path(mesh.geometry_image);
    if (std::filesystem::exists(path)) {
      if (!load_thickness_map(path, thickness[m], error))
        return false;
      if (thickness[m].size != images[m].size) {
        error = path + ": " + std::to_string(thickness[m].size) + "^2 does not match the " +
                std::to_string(images[m].size) + "^2 geometry image";
        return false;
      }
      thickness_layer_[m] = int(m);
      thickness_side = std::max(thickness_side, thickness[m].size);
    } else {
      thickness_missing_.push_back(path);
    }
  }
  // Rasterised: the parameterised mesh the image was made from (NAME.gimage.obj, the surface
  // itself with its smooth normals and corner uvs into the image's maps), else the image's grid.
  std::vector<ParameterizedMesh> raster(scene.meshes.size());
  std::vector<const GeometryImage*> image_pointers;
  std::vector<const ParameterizedMesh*> mesh_pointers;
  for (size_t m = 0; m < images.size(); ++m) {
    image_pointers.push_back(&images[m]);
    const std::string path = parameterized_mesh_path(scene.meshes[m].geometry_image);
    const bool has_mesh = std::filesystem::exists(path);
    if (has_mesh &&
        !load_parameterized_mesh_of(images[m], scene.meshes[m].geometry_image, raster[m], error))
      return false;
    mesh_pointers.push_back(has_mesh ? &raster[m] : nullptr);
  }
  if (!assets_.upload(image_pointers, std::vector<const GeometryField*>(images.size(), nullptr),
                      error, mesh_pointers)) {
    error = scene.filename + ": " + error;
    return false;
  }
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &thickness_);
  glTextureStorage3D(thickness_, 1, GL_R32F, thickness_side, thickness_side,
                     GLsizei(std::max<size_t>(1, thickness.size())));
  for (size_t m = 0; m < thickness.size(); ++m)
    if (thickness_layer_[m] >= 0)
      glTextureSubImage3D(thickness_, 0, 0, 0, GLint(m), thickness[m].size, thickness[m].size, 1,
                          GL_RED, GL_FLOAT, thickness[m].distance.data());

  if (!upload_environment_texture(scene_.environment, environment_, error))
    return false;

  create_proxy_cube(proxy_buffer_, proxy_vertex_array_);
  glCreateVertexArrays(1, &empty_vertex_array_);
  glCreateFramebuffers(1, &cube_framebuffer_);
  update_scene();

  const std::vector<std::pair<ShaderProgram*, std::vector<std::string>>> programs = {
      {&forward_program_, {"image_space_object.vert", "image_space_forward.frag"}},
      {&surfaces_program_, {"image_space_object.vert", "image_space_surfaces.frag"}},
      {&background_program_, {"fullscreen.vert", "image_space_background.frag"}},
      {&cubemap_program_, {"image_space_object.vert", "cubemap_surface.frag"}},
      {&wyman2005_program_, {"image_space_object.vert", "wyman2005_refract.frag"}},
      {&davis_wyman_program_, {"image_space_object.vert", "davis_wyman_refract.frag"}},
  };
  for (const auto& [program, stages] : programs)
    if (!program->build(shader_dir, stages, "", error))
      return false;
  return true;
}

bool ImageSpaceRenderer::supports(ImageSpaceMethod method, std::string& error) const {
  if (method != ImageSpaceMethod::kWyman2005)
    return true;
  for (const SceneObject& o : scene_.objects) {
    if (o.shape.type != ShapeType::kMesh || o.material.type != MaterialType::kDielectric ||
        thickness_layer_[size_t(o.shape.mesh)] >= 0)
      continue;
    const std::string& image = scene_.meshes[size_t(o.shape.mesh)].geometry_image;
    const std::string name = image.substr(0, image.size() - std::string(".gimage.exr").size());
    error = thickness_path(image) +
            ": missing; wyman2005 needs d_n (make it with: gfield thickness " + name + ")";
    return false;
  }
  return true;
}

glm::vec2 ImageSpaceRenderer::eye_depth_range(const View& view, bool dielectrics) const {
  glm::vec2 range(3.0e38f, -3.0e38f);
  for (int k = 0; k < int(scene_.objects.size()); ++k) {
    if ((scene_.objects[size_t(k)].material.type == MaterialType::kDielectric) != dielectrics)
      continue;
    glm::vec3 lo, hi;
    object_world_bounds(scene_, assets_, k, lo, hi);
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
      const float z = glm::dot(corner - view.position, view.forward);
      range = glm::vec2(std::min(range.x, z), std::max(range.y, z));
    }
  }
  if (range.x > range.y)
    return view.near_far;
  // A margin of 1% of the scene against rounding at the bounds.
  const float margin = 0.01f * extent_;
  return glm::vec2(std::max(view.near_far.x, range.x - margin),
                   std::min(view.near_far.y, range.y + margin));
}

void ImageSpaceRenderer::update_scene() {
  extent_ = upload_scene_buffers(scene_, assets_, objects_buffer_, lights_buffer_);
  cubes_.resize(scene_.objects.size());
}

void ImageSpaceRenderer::release_map(ScreenMap& map) {
  if (map.framebuffer != 0)
    glDeleteFramebuffers(1, &map.framebuffer);
  if (map.texture != 0)
    glDeleteTextures(1, &map.texture);
  if (map.depth != 0)
    glDeleteRenderbuffers(1, &map.depth);
  map = ScreenMap{};
}

bool ImageSpaceRenderer::ensure_map(ScreenMap& map, int width, int height) {
  if (map.framebuffer != 0 && map.width == width && map.height == height)
    return true;
  release_map(map);
  glCreateTextures(GL_TEXTURE_2D, 1, &map.texture);
  glTextureStorage2D(map.texture, 1, GL_RGBA32F, width, height);
  glTextureParameteri(map.texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(map.texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glCreateRenderbuffers(1, &map.depth);
  glNamedRenderbufferStorage(map.depth, GL_DEPTH_COMPONENT32F, width, height);
  glCreateFramebuffers(1, &map.framebuffer);
  glNamedFramebufferTexture(map.framebuffer, GL_COLOR_ATTACHMENT0, map.texture, 0);
  glNamedFramebufferRenderbuffer(map.framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, map.depth);
  map.width = width;
  map.height = height;
  return glCheckNamedFramebufferStatus(map.framebuffer, GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

bool ImageSpaceRenderer::ensure_cube(CubeMap& cube, int size) {
  if (cube.texture != 0 && cube.size == size)
    return true;
  if (cube.texture != 0)
    glDeleteTextures(1, &cube.texture);
  if (cube.depth != 0)
    glDeleteRenderbuffers(1, &cube.depth);
  glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &cube.texture);
  glTextureStorage2D(cube.texture, 1, GL_RGBA16F, size, size);
  glTextureParameteri(cube.texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(cube.texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glCreateRenderbuffers(1, &cube.depth);
  glNamedRenderbufferStorage(cube.depth, GL_DEPTH_COMPONENT32F, size, size);
  cube.size = size;
  return true;
}

void ImageSpaceRenderer::set_common_uniforms(const ShaderProgram& program, const View& view) const {
  const auto u = [&](const char* name) { return program.uniform(name); };
  glUseProgram(program.id());
  glUniform1i(u("u_object_count"), int(scene_.objects.size()));
  glUniform1i(u("u_light_count"), int(scene_.lights.size()));
  glUniform3fv(u("u_ambient"), 1, &scene_.ambient.x);
  glUniform1f(u("u_scene_extent"), extent_);
  glUniform1i(u("u_env_type"), int(scene_.environment.type));
  glUniform3fv(u("u_env_color"), 1, &scene_.environment.color.x);
  glUniform1f(u("u_env_intensity"), scene_.environment.intensity);
  glUniform3fv(u("u_camera_position"), 1, &view.position.x);
  glUniform3fv(u("u_camera_forward"), 1, &view.forward.x);
  glUniform3fv(u("u_camera_right"), 1, &view.right.x);
  glUniform3fv(u("u_camera_up"), 1, &view.up.x);
  glUniform2fv(u("u_tan_half"), 1, &view.tan_half.x);
  glUniform2f(u("u_image_size"), float(view.width), float(view.height));
  glUniform2fv(u("u_near_far"), 1, &view.near_far.x);
  glUniform2fv(u("u_jitter"), 1, &view.jitter.x);
  glUniform2fv(u("u_refractor_depths"), 1, &view.refractor_depths.x);
  glUniform2fv(u("u_nearby_depths"), 1, &view.nearby_depths.x);
  glUniformMatrix4fv(u("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view.view_projection));
  glUniform3fv(u("u_eye"), 1, &view.position.x);
  glUniform3fv(u("u_forward"), 1, &view.forward.x);
  glUniform1i(u("u_facing"), 0);
}

void ImageSpaceRenderer::draw_object(const ShaderProgram& program, int object) const {
  const SceneObject& o = scene_.objects[size_t(object)];
  const auto u = [&](const char* name) { return program.uniform(name); };
  const glm::mat4 to_world(object_to_world(o.transform));
  glUniformMatrix4fv(u("u_to_world"), 1, GL_FALSE, glm::value_ptr(to_world));
  glUniform1i(u("u_object"), object);
  glUniform1f(u("u_alpha"), o.material.ior);
  if (o.shape.type == ShapeType::kMesh) {
    const GpuAsset& asset = assets_.assets()[size_t(o.shape.mesh)];
    glUniform3f(u("u_proxy_half"), 1.0f, 1.0f, 1.0f);
    glUniform1i(u("u_thickness_layer"), thickness_layer_[size_t(o.shape.mesh)]);
    glUniform1i(u("u_gi_size"), asset.image_size);
    glBindVertexArray(asset.vertex_array);
    glDrawElements(GL_TRIANGLES, asset.index_count, GL_UNSIGNED_INT, nullptr);
  } else {
    // A slightly grown box: the exact shape is found per fragment.
    const glm::vec3 half = shape_half_extent(o.shape) * 1.001f + 1e-5f * extent_;
    glUniform3fv(u("u_proxy_half"), 1, &half.x);
    glUniform1i(u("u_thickness_layer"), -1);
    glBindVertexArray(proxy_vertex_array_);
    glDrawArrays(GL_TRIANGLES, 0, 36);
  }
}

void ImageSpaceRenderer::render_cube_map(int object, int size) {
  CubeMap& cube = cubes_[size_t(object)];
  ensure_cube(cube, size);
  glm::vec3 lo, hi;
  object_world_bounds(scene_, assets_, object, lo, hi);
  const glm::vec3 centre = 0.5f * (lo + hi);
  // OpenGL cube faces +X, -X, +Y, -Y, +Z, -Z: view direction and up of each.
  const glm::vec3 directions[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  const float near_plane = 1e-3f * extent_, far_plane = 4.0f * extent_;
  const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, near_plane, far_plane);
  View view;
  view.position = centre;
  view.tan_half = glm::vec2(1.0f);
  view.near_far = glm::vec2(near_plane, far_plane);
  view.width = view.height = size;
  glNamedFramebufferRenderbuffer(cube_framebuffer_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 cube.depth);
  glBindFramebuffer(GL_FRAMEBUFFER, cube_framebuffer_);
  glViewport(0, 0, size, size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  for (int face = 0; face < 6; ++face) {
    glNamedFramebufferTextureLayer(cube_framebuffer_, GL_COLOR_ATTACHMENT0, cube.texture, 0, face);
    const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, clear);
    glClear(GL_DEPTH_BUFFER_BIT);
    view.forward = directions[face];
    view.up = -ups[face];
    view.right = glm::cross(view.forward, view.up);
    view.view_projection = projection * glm::lookAt(centre, centre + directions[face], ups[face]);
    set_common_uniforms(forward_program_, view);
    glUniform1i(forward_program_.uniform("u_alpha_is_coverage"), 1);
    for (int k = 0; k < int(scene_.objects.size()); ++k)
      if (k != object)
        draw_object(forward_program_, k);
  }
}

void ImageSpaceRenderer::render_surface_map(ScreenMap& map, const View& view, int facing) {
  glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer);
  glViewport(0, 0, map.width, map.height);
  const float clear[4] = {0.0f, 0.0f, 0.0f, kFar};
  glClearBufferfv(GL_COLOR, 0, clear);
  glClear(GL_DEPTH_BUFFER_BIT);
  set_common_uniforms(surfaces_program_, view);
  glUniform1i(surfaces_program_.uniform("u_facing"), facing);
  for (int k = 0; k < int(scene_.objects.size()); ++k)
    if (scene_.objects[size_t(k)].material.type == MaterialType::kDielectric)
      draw_object(surfaces_program_, k);
}

void ImageSpaceRenderer::render_nearby_map(ScreenMap& map, const View& view) {
  glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer);
  glViewport(0, 0, map.width, map.height);
  const float clear[4] = {0.0f, 0.0f, 0.0f, kFar};
  glClearBufferfv(GL_COLOR, 0, clear);
  glClear(GL_DEPTH_BUFFER_BIT);
  set_common_uniforms(forward_program_, view);
  glUniform1i(forward_program_.uniform("u_alpha_is_coverage"), 0);
  for (int k = 0; k < int(scene_.objects.size()); ++k)
    if (scene_.objects[size_t(k)].material.type != MaterialType::kDielectric)
      draw_object(forward_program_, k);
}

void ImageSpaceRenderer::render(const Camera& camera, const ImageSpaceSettings& settings,
                                Framebuffer& target, glm::vec2 jitter, ImageSpaceStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const ImageSpaceMethod method = settings.method;
  View view;
  view.width = target.width();
  view.height = target.height();
  const float aspect = float(view.width) / float(view.height);
  const float far_plane = 4.0f * extent_ + glm::length(camera.target - camera.position);
  view.near_far = glm::vec2(1e-4f * far_plane, far_plane);
  view.position = camera.position;
  view.forward = glm::normalize(camera.target - camera.position);
  view.right = glm::normalize(glm::cross(view.forward, camera.up));
  view.up = glm::cross(view.right, view.forward);
  const float tan_half = std::tan(glm::radians(camera.fov_degrees) * 0.5f);
  view.tan_half = glm::vec2(tan_half * aspect, tan_half);
  view.view_projection =
      glm::perspective(glm::radians(camera.fov_degrees), aspect, view.near_far.x, view.near_far.y) *
      glm::lookAt(camera.position, camera.target, camera.up);
  view.refractor_depths = eye_depth_range(view, true);
  view.nearby_depths = eye_depth_range(view, false);

  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, objects_buffer_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, lights_buffer_);
  glBindTextureUnit(0, assets_.positions());
  glBindTextureUnit(1, assets_.normals());
  glBindTextureUnit(2, assets_.fields());
  glBindTextureUnit(kUnitEnvironment, environment_);
  glBindTextureUnit(kUnitThickness, thickness_);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

  // Passes before the picture: cube maps, or the screen maps at the buffer resolution.
  const int objects = int(scene_.objects.size());
  const bool cube_method =
      method == ImageSpaceMethod::kCubeMap || method == ImageSpaceMethod::kEnvMap;
  if (cube_method) {
    for (int k = 0; k < objects; ++k)
      if (is_special(scene_.objects[size_t(k)], method))
        render_cube_map(k, std::max(1, settings.cube_size));
  } else {
    View small = view;
    small.width = std::max(1, int(std::lround(float(view.width) * settings.buffer_scale)));
    small.height = std::max(1, int(std::lround(float(view.height) * settings.buffer_scale)));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    ensure_map(back_, small.width, small.height);
    render_surface_map(back_, small, -1);
    if (method == ImageSpaceMethod::kDavisWyman) {
      ensure_map(front_, small.width, small.height);
      render_surface_map(front_, small, 1);
    }
    if (settings.background == ExitBackground::kDepthMap) {
      ensure_map(nearby_, small.width, small.height);
      render_nearby_map(nearby_, small);
    }
  }
  double pass_ms = 0.0;
  if (stats != nullptr) {
    glFinish();
    pass_ms = elapsed_ms(start);
  }

  // The picture: the environment, opaque objects, then the method's objects, at the sample
  // offset.
  view.jitter = jitter;
  view.view_projection =
      jittered_projection(glm::perspective(glm::radians(camera.fov_degrees), aspect,
                                           view.near_far.x, view.near_far.y),
                          jitter, view.width, view.height) *
      glm::lookAt(camera.position, camera.target, camera.up);
  target.bind();
  glClear(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  set_common_uniforms(background_program_, view);
  glBindVertexArray(empty_vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  set_common_uniforms(forward_program_, view);
  glUniform1i(forward_program_.uniform("u_alpha_is_coverage"), 1);
  for (int k = 0; k < objects; ++k)
    if (!is_special(scene_.objects[size_t(k)], method))
      draw_object(forward_program_, k);

  const ShaderProgram& program = cube_method                              ? cubemap_program_
                                 : method == ImageSpaceMethod::kWyman2005 ? wyman2005_program_
                                                                          : davis_wyman_program_;
  set_common_uniforms(program, view);
  const auto u = [&](const char* name) { return program.uniform(name); };
  glUniform1i(u("u_facing"), 1);
  glUniform1i(u("u_reflect_only"), method == ImageSpaceMethod::kEnvMap ? 1 : 0);
  glUniform1i(u("u_per_vertex"), settings.per_vertex ? 1 : 0);
  glUniform1i(u("u_fresnel"), settings.fresnel ? 1 : 0);
  glUniform1i(u("u_bounces"), std::max(0, settings.bounces));
  glUniform1i(u("u_iterations_first"), std::max(0, settings.iterations_first));
  glUniform1i(u("u_iterations_later"), std::max(0, settings.iterations_later));
  glUniform1i(u("u_exit_iterations"), std::max(0, settings.exit_iterations));
  glUniform1i(u("u_back_only_later"), settings.back_only_later ? 1 : 0);
  glUniform1i(u("u_background"), int(settings.background));
  glUniform1f(u("u_min_alignment"), settings.min_alignment);
  glUniform1f(u("u_offset"), 1e-3f * extent_);
  glBindTextureUnit(kUnitBack, back_.texture);
  glBindTextureUnit(kUnitFront, front_.texture);
  glBindTextureUnit(kUnitNearby, nearby_.texture);
  for (int k = 0; k < objects; ++k) {
    if (!is_special(scene_.objects[size_t(k)], method))
      continue;
    if (cube_method)
      glBindTextureUnit(kUnitCube, cubes_[size_t(k)].texture);
    draw_object(program, k);
  }
  if (stats != nullptr) {
    glFinish();
    stats->milliseconds += elapsed_ms(start);
    stats->pass_milliseconds += pass_ms;
  }
}

Image ImageSpaceRenderer::render_image(int width, int height, const ImageSpaceSettings& settings,
                                       ImageSpaceStats* stats) {
  return render_supersampled(width, height, settings.samples_per_pixel,
                             [&](Framebuffer& target, glm::vec2 jitter) {
                               render(scene_.camera, settings, target, jitter, stats);
                             });
}

bool ImageSpaceRenderer::reload_shaders_if_changed(std::string& error) {
  bool rebuilt = false;
  error.clear();
  for (ShaderProgram* program : {&forward_program_, &surfaces_program_, &background_program_,
                                 &cubemap_program_, &wyman2005_program_, &davis_wyman_program_}) {
    std::string program_error;
    rebuilt |= program->reload_if_changed(program_error);
    error += program_error;
  }
  return rebuilt && error.empty();
}

}  // namespace gfield
