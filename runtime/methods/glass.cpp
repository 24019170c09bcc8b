#include "runtime/methods/glass.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "geometry/analytic_primitives.hpp"
#include "gfield/glass_displacement.hpp"
#include "gfield/gpu_contract.hpp"
#include "gfield/stopwatch.hpp"

namespace gfield {

MethodInfo GlassMethod::info() const {
  return {"glass", "glass by vertex displacement (Mukai et al. 2013)"};
}

std::vector<MethodOption> GlassMethod::options() {
  return {
      choice_option("glass-verge", "hollow cylinder's verge",
                    "glass: the hollow cylinder's verge displaced (the paper) or traced per pixel",
                    &settings_.trace_verge, {"displaced", "traced"}),
      flag_option("no-glass-fresnel", "Fresnel at the glass",
                  "glass: no Fresnel transmittance and reflection at the glass", &settings_.fresnel,
                  false),
  };
}

bool GlassMethod::find_glass(std::string& error) {
  const Scene& scene = scene_->scene();
  glass_object_ = -1;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    if (o.material.type == MaterialType::kMirror) {
      error = scene.filename + ": the glass method draws no mirrors (object \"" + o.name + "\")";
      return false;
    }
    if (o.material.type != MaterialType::kDielectric)
      continue;
    if (glass_object_ >= 0) {
      error = scene.filename + ": the glass method takes one glass object (\"" +
              scene.objects[size_t(glass_object_)].name + "\" and \"" + o.name + "\")";
      return false;
    }
    if (o.shape.type != ShapeType::kSlab && o.shape.type != ShapeType::kHollowCylinder) {
      error = scene.filename + ": the glass method's glass is a slab or a hollow cylinder (\"" +
              o.name + "\" is a " + shape_name(o.shape.type) + ")";
      return false;
    }
    glass_object_ = int(k);
  }
  if (glass_object_ < 0) {
    error = scene.filename + ": the glass method needs a dielectric slab or hollow cylinder";
    return false;
  }
  const SceneObject& glass = scene.objects[size_t(glass_object_)];
  GlassCylinder cylinder;
  glm::mat4 to_world;
  if (glass.shape.type == ShapeType::kHollowCylinder &&
      !glass_cylinder(glass, cylinder, to_world, error)) {
    error = scene.filename + ": " + error;
    return false;
  }
  return true;
}

bool GlassMethod::load(GpuScene& scene, const std::filesystem::path& shader_dir,
                       std::string& error) {
  scene_ = &scene;
  AssetNeeds needs;
  needs.source_meshes = true;
  if (!find_glass(error) || !scene.require(needs, error))
    return false;
  update_geometry();
  // Analytic opaque objects: tessellated once in object space, edges from the scene's extent.
  const Scene& s = scene.scene();
  tessellated_ = std::vector<GpuMesh>(s.objects.size());
  for (size_t k = 0; k < s.objects.size(); ++k) {
    const SceneObject& o = s.objects[k];
    if (int(k) == glass_object_ || o.shape.type == ShapeType::kMesh)
      continue;
    TriangleSoup soup;
    if (!tessellate(o.shape, settings_.max_edge * extent_, soup)) {
      error = s.filename + ": the glass method cannot draw \"" + o.name + "\" (a " +
              shape_name(o.shape.type) + ") as an opaque object";
      return false;
    }
    tessellated_[k].upload(soup.vertices, soup.indices);
  }
  if (!peel_program_.build(shader_dir, {"glass_peel.vert", "glass_peel.frag"}, "", error) ||
      !scene_program_.build(shader_dir, {"glass_scene.vert", "glass_scene.frag"}, "", error) ||
      !shadow_program_.build(shader_dir, {"glass_shadow.vert", "glass_shadow.frag"}, "", error) ||
      !composite_program_.build(shader_dir, {"fullscreen.vert", "glass_composite.frag"}, "", error))
    return false;
  const int lights = std::max(1, std::min(int(s.lights.size()), gpu::GLASS_SHADOWED_LIGHTS));
  shadow_maps_.make(GL_TEXTURE_2D_ARRAY);
  const GLuint maps = shadow_maps_.id();
  glTextureStorage3D(maps, 1, GL_DEPTH_COMPONENT32F, settings_.shadow_map_size,
                     settings_.shadow_map_size, lights);
  glTextureParameteri(maps, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(maps, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTextureParameteri(maps, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(maps, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(maps, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(maps, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  shadow_framebuffer_.make();
  render_shadow_maps();
  return true;
}

void GlassMethod::update_geometry() {
  const Scene& scene = scene_->scene();
  // Bounds of the camera, the analytic shapes and the mesh files' vertices: the extent.
  lo_ = hi_ = scene.camera.position;
  for (const SceneObject& o : scene.objects) {
    const glm::mat4 to_world(object_to_world(o.transform));
    if (o.shape.type == ShapeType::kMesh) {
      const Box& b = scene_->assets().asset(o.shape.mesh).mesh_bounds;
      grow_world_bounds(to_world, b.min, b.max, lo_, hi_);
    } else {
      glm::dvec3 olo, ohi;
      shape_bounds(o.shape, olo, ohi);
      grow_world_bounds(to_world, glm::vec3(olo), glm::vec3(ohi), lo_, hi_);
    }
  }
  extent_ = std::max(1e-3f, glm::length(hi_ - lo_));
  // The glass for peeling, in world space.
  const GlassSoup soup = glass_triangles(scene.objects[size_t(glass_object_)]);
  glass_vertex_count_ = GLsizei(soup.data.size() / 4);
  glass_buffer_.make();
  glNamedBufferStorage(glass_buffer_.id(), GLsizeiptr(soup.data.size() * sizeof(float)),
                       soup.data.data(), 0);
  const GLuint array = glass_vertex_array_.make();
  glVertexArrayVertexBuffer(array, 0, glass_buffer_.id(), 0, 4 * sizeof(float));
  glEnableVertexArrayAttrib(array, 0);
  glVertexArrayAttribFormat(array, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(array, 0, 0);
  glEnableVertexArrayAttrib(array, 1);
  glVertexArrayAttribFormat(array, 1, 1, GL_FLOAT, GL_FALSE, 3 * sizeof(float));
  glVertexArrayAttribBinding(array, 1, 0);
}

void GlassMethod::scene_changed() {
  std::string ignored;
  if (scene_ == nullptr || !find_glass(ignored))
    return;
  update_geometry();
  render_shadow_maps();
}

long long GlassMethod::vertex_count() const {
  long long n = 0;
  const Scene& scene = scene_->scene();
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    if (int(k) == glass_object_)
      continue;
    n += o.shape.type == ShapeType::kMesh ? scene_->assets().asset(o.shape.mesh).source.vertex_count
                                          : tessellated_[k].vertex_count;
  }
  return n;
}

void GlassMethod::draw_opaque(const ShaderProgram& program) const {
  const Scene& scene = scene_->scene();
  for (int k = 0; k < int(scene.objects.size()); ++k) {
    if (k == glass_object_)
      continue;
    const SceneObject& o = scene.objects[size_t(k)];
    glUniform1i(program.uniform_if_declared("u_smooth"),  // the scene pass's, not the shadows'
                o.shape.type != ShapeType::kMesh || o.shape.smooth_normals ? 1 : 0);
    if (o.shape.type == ShapeType::kMesh) {
      scene_->draw_object(program, k, RasterMesh::kSource);
    } else {
      scene_->set_object_uniforms(program, k);
      tessellated_[size_t(k)].draw();
    }
  }
}

void GlassMethod::render_shadow_maps() {
  light_view_projection_.assign(gpu::GLASS_SHADOWED_LIGHTS, glm::mat4(1.0f));
  const glm::vec3 centre = 0.5f * (lo_ + hi_);
  const float radius = 0.5f * glm::length(hi_ - lo_) + 1e-3f;
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_framebuffer_.id());
  glViewport(0, 0, settings_.shadow_map_size, settings_.shadow_map_size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  glUseProgram(shadow_program_.id());
  const Scene& scene = scene_->scene();
  for (size_t i = 0; i < scene.lights.size() && i < size_t(gpu::GLASS_SHADOWED_LIGHTS); ++i) {
    const Light& light = scene.lights[i];
    if (light.type != LightType::kDirectional)
      continue;
    const glm::vec3 d = glm::normalize(light.direction);
    const glm::vec3 up = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::mat4 view = glm::lookAt(centre - 2.0f * radius * d, centre, up);
    light_view_projection_[i] =
        glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius) * view;
    glNamedFramebufferTextureLayer(shadow_framebuffer_.id(), GL_DEPTH_ATTACHMENT, shadow_maps_.id(),
                                   0, GLint(i));
    glNamedFramebufferDrawBuffer(shadow_framebuffer_.id(), GL_NONE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniformMatrix4fv(shadow_program_.uniform("u_light_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(light_view_projection_[i]));
    draw_opaque(shadow_program_);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void GlassMethod::set_light_uniforms(const ShaderProgram& program) const {
  scene_->set_uniforms(program);
  glUniformMatrix4fv(program.uniform("u_light_view_projection"), gpu::GLASS_SHADOWED_LIGHTS,
                     GL_FALSE, glm::value_ptr(light_view_projection_[0]));
  glBindTextureUnit(gpu::UNIT_SHADOW_MAPS, shadow_maps_.id());
}

void GlassMethod::ClassImages::ensure(int w, int h, int class_layers) {
  class_layers = std::max(class_layers, 1);
  if (images && w == width && h == height && class_layers <= layers)
    return;
  images.make(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(images.id(), 1, GL_RGBA32F, w, h, class_layers);
  depth.make();
  glNamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, w, h);
  framebuffer.make();
  glNamedFramebufferRenderbuffer(framebuffer.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 depth.id());
  width = w;
  height = h;
  layers = class_layers;
}

void GlassMethod::peel(const glm::mat4& view_projection, int width, int height) {
  PassClock clock(timed_);
  glUseProgram(peel_program_.id());
  glUniformMatrix4fv(peel_program_.uniform("u_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(view_projection));
  glBindVertexArray(glass_vertex_array_.id());
  glBindTextureUnit(gpu::UNIT_CLASS_IMAGES, class_images_.images.id());
  const float no_layer[4] = {-1.0f, 2.0f, 0.0f, 0.0f};
  for (int k = 0; k < gpu::GLASS_LAYERS; ++k) {
    layers_[k].resize(width, height, {GL_RGBA32F}, GL_DEPTH_COMPONENT32F);
    layers_[k].bind();
    glClearBufferfv(GL_COLOR, 0, no_layer);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniform1i(peel_program_.uniform("u_first"), k == 0 ? 1 : 0);
    if (k > 0)
      glBindTextureUnit(gpu::UNIT_PEEL_PREVIOUS, layers_[k - 1].texture(0));
    glDrawArrays(GL_TRIANGLES, 0, glass_vertex_count_);
  }
  peel_ms_ = clock.read();
  peel_gpu_ms_ = clock.gpu_ms(0);
}

void GlassMethod::set_class_uniforms(int refraction_class) {
  const SceneObject& glass = scene_->scene_object(glass_object_);
  const auto u = [&](const char* name) { return scene_program_.uniform(name); };
  int kind = 0;
  if (refraction_class >= 1 && refraction_class <= 3) {
    kind = 1;
    const GlassPlate plate = glass_plate(glass, refraction_class - 1);
    glUniform3fv(u("u_plate_centre"), 1, &plate.centre.x);
    glUniform3fv(u("u_plate_normal"), 1, &plate.normal.x);
    glUniform1f(u("u_plate_thickness"), plate.thickness);
  } else if (refraction_class >= 4) {
    kind = 2;
    glUniform1i(u("u_path"), refraction_class - 4);
  }
  glUniform1i(u("u_glass"), kind);
}

void GlassMethod::draw_class_images(const Camera& camera, const std::vector<int>& classes,
                                    const glm::mat4& view_projection, int layer_of_class[]) {
  const SceneObject& glass = scene_->scene_object(glass_object_);
  const int width = class_images_.width, height = class_images_.height;
  const auto u = [&](const char* name) { return scene_program_.uniform(name); };
  glUseProgram(scene_program_.id());
  scene_->bind();
  set_light_uniforms(scene_program_);
  glUniformMatrix4fv(u("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
  glUniform3fv(u("u_eye"), 1, &camera.position.x);
  glUniform1f(u("u_ior"), glass.material.ior);
  if (glass.shape.type == ShapeType::kHollowCylinder) {
    GlassCylinder cylinder;
    glm::mat4 to_world(1.0f);
    std::string ignored;
    glass_cylinder(glass, cylinder, to_world, ignored);
    const glm::mat4 to_object = glm::inverse(to_world);
    glUniformMatrix4fv(u("u_cylinder_to_object"), 1, GL_FALSE, glm::value_ptr(to_object));
    glUniformMatrix4fv(u("u_cylinder_to_world"), 1, GL_FALSE, glm::value_ptr(to_world));
    glUniform1f(u("u_outer_radius"), cylinder.outer_radius);
    glUniform1f(u("u_inner_radius"), cylinder.inner_radius);
  }
  std::fill(layer_of_class, layer_of_class + kGlassClasses, -1);
  const float no_hit[4] = {0.0f, 0.0f, 0.0f, 2.0f};
  const GLuint framebuffer = class_images_.framebuffer.id();
  for (size_t i = 0; i < classes.size(); ++i) {
    if (i == 1)  // class 0 is drawn: its depth is the scene's for the peeling
      peel(view_projection, width, height);
    glUseProgram(scene_program_.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    layer_of_class[classes[i]] = int(i);
    glNamedFramebufferTextureLayer(framebuffer, GL_COLOR_ATTACHMENT0, class_images_.images.id(), 0,
                                   GLint(i));
    glNamedFramebufferDrawBuffer(framebuffer, GL_COLOR_ATTACHMENT0);
    glClearBufferfv(GL_COLOR, 0, no_hit);
    glClear(GL_DEPTH_BUFFER_BIT);
    set_class_uniforms(classes[i]);
    draw_opaque(scene_program_);
  }
  if (classes.size() == 1)
    peel(view_projection, width, height);
}

void GlassMethod::composite(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
                            const CameraFrustum& frustum, const int layer_of_class[]) {
  const SceneObject& glass = scene_->scene_object(glass_object_);
  target.bind();
  glDisable(GL_DEPTH_TEST);
  const ShaderProgram& p = composite_program_;
  glUseProgram(p.id());
  const auto u = [&](const char* name) { return p.uniform(name); };
  for (int k = 0; k < gpu::GLASS_LAYERS; ++k)
    glBindTextureUnit(GLuint(gpu::UNIT_PEEL_LAYERS + k), layers_[k].texture(0));
  glBindTextureUnit(gpu::UNIT_CLASS_IMAGES, class_images_.images.id());
  scene_->bind();
  set_light_uniforms(p);
  glUniform1iv(u("u_layer_of_class"), kGlassClasses, layer_of_class);
  const glm::mat4 glass_to_object(glm::inverse(object_to_world(glass.transform)));
  glUniform1i(u("u_glass_shape"), int(glass.shape.type));
  glUniform4f(u("u_glass_params"), glass.shape.radius, glass.shape.height, glass.shape.thickness,
              0.0f);
  glUniform3fv(u("u_glass_size"), 1, &glass.shape.size.x);
  glUniformMatrix4fv(u("u_glass_to_object"), 1, GL_FALSE, glm::value_ptr(glass_to_object));
  glUniform1f(u("u_ior"), glass.material.ior);
  glUniform3fv(u("u_absorption"), 1, &glass.material.absorption.x);
  glUniform1i(u("u_fresnel"), settings_.fresnel ? 1 : 0);
  glUniform1i(u("u_trace_verge"), settings_.trace_verge ? 1 : 0);
  glUniform1f(u("u_epsilon"), 1e-5f * extent_);
  const glm::mat4 view_projection = frustum.projection * frustum.view;
  glUniformMatrix4fv(u("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
  glUniform1f(u("u_near"), frustum.near_plane);
  glUniform1f(u("u_far"), frustum.far_plane);
  glUniform1f(u("u_scene_extent"), extent_);
  const bool has_meshes =
      std::any_of(scene_->scene().objects.begin(), scene_->scene().objects.end(),
                  [](const SceneObject& o) { return o.shape.type == ShapeType::kMesh; });
  glUniform1i(u("u_has_meshes"), has_meshes ? 1 : 0);
  set_camera_uniforms(p, camera, target.width(), target.height(), jitter);
  scene_->draw_fullscreen();
}

void GlassMethod::render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
                         FrameStats* stats) {
  timed_ = stats != nullptr;
  PassClock clock(timed_);
  const int width = target.width(), height = target.height();
  const SceneObject& glass = scene_->scene_object(glass_object_);
  const std::vector<int> classes =
      classes_present(glass, camera, float(width) / float(height), settings_.trace_verge);
  class_images_.ensure(width, height, int(classes.size()));
  const CameraFrustum frustum = camera_frustum(camera, width, height, *scene_, jitter);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  int layer_of_class[kGlassClasses];
  draw_class_images(camera, classes, frustum.projection * frustum.view, layer_of_class);
  const double scene_ms = clock.read() - peel_ms_;
  const double scene_gpu_ms = clock.gpu_ms(0) - peel_gpu_ms_;
  composite(camera, target, jitter, frustum, layer_of_class);
  if (stats == nullptr)
    return;
  add_frame_time(stats, clock, "peeling", peel_ms_, peel_gpu_ms_);
  stats->add_part("class images", scene_ms);
  stats->add_gpu_part("class images", scene_gpu_ms);
  stats->add_count("class images", double(classes.size()));
  stats->add_count("opaque vertices", double(vertex_count()));
}

bool GlassMethod::reload_shaders_if_changed(std::string& error) {
  return reload_programs_if_changed(
      {&peel_program_, &scene_program_, &shadow_program_, &composite_program_}, error);
}

}  // namespace gfield
