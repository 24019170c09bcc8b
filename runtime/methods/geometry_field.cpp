#include "runtime/methods/geometry_field.hpp"

#include <cstdio>

#include <glm/gtc/type_ptr.hpp>

#include "gfield/gpu_contract.hpp"
#include "gfield/stopwatch.hpp"

namespace gfield {

MethodInfo GeometryFieldMethod::info() const {
  return {"field", "geometry field (Li et al. 2006)"};
}

std::vector<MethodOption> GeometryFieldMethod::options() {
  GeometryFieldSettings& s = settings_;
  return {
      choice_option("mode", "lookup", "Geometry-field lookup: nearest, linear or refined", &s.mode,
                    {"nearest", "linear", "refined"}),
      choice_option("field-bits", "field bits",
                    "Bits per uv component of the fields on the GPU: 8 (RG8), 16 (RG16) or 32 "
                    "(RG32F)",
                    &s.field_bits, {"8", "16", "32"}),
      int_option("depth", "depth",
                 "Reflections/refractions after the camera ray (as gfield render --depth)",
                 &s.max_depth, 0, 64),
      flag_option("no-self-reflection", "self-reflection",
                  "Objects do not look up their own field (no self-reflection, no self-shadows)",
                  &s.self_reflection, false),
      float_option("min-weight", "min weight", "Branches below this weight are dropped",
                   &s.min_weight, 0.0f, 1.0f),
      int_option("max-rays", "max rays / pixel", "Secondary rays per pixel at most", &s.max_rays, 1,
                 256),
  };
}

AssetNeeds GeometryFieldMethod::needs() const {
  AssetNeeds needs;
  needs.fields = true;
  needs.field_bits = field_bits(settings_.field_bits);
  needs.source_meshes = true;  // the G-buffer holds the surfaces the reference tracer sees
  return needs;
}

bool GeometryFieldMethod::load(GpuScene& scene, const std::filesystem::path& shader_dir,
                               std::string& error) {
  scene_ = &scene;
  return scene.require(needs(), error) &&
         gbuffer_program_.build(shader_dir, {"gbuffer.vert", "gbuffer.frag"}, "", error) &&
         trace_program_.build(shader_dir, {"fullscreen.vert", "field_trace.frag"}, "", error);
}

void GeometryFieldMethod::render_gbuffer(const Camera& camera, int width, int height,
                                         glm::vec2 jitter) {
  gbuffer_.resize(width, height, {GL_RGBA32F, GL_RGBA32F, GL_RGBA32F, GL_RGBA32F},
                  GL_DEPTH_COMPONENT32F);
  gbuffer_.bind();
  const float clear_position[4] = {0.0f, 0.0f, 0.0f, -1.0f};
  const float clear_zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, clear_position);
  for (int k = 1; k < 4; ++k)
    glClearBufferfv(GL_COLOR, k, clear_zero);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const CameraFrustum f = camera_frustum(camera, width, height, *scene_, jitter);
  const glm::mat4 view_projection = f.projection * f.view;
  glUseProgram(gbuffer_program_.id());
  scene_->bind();
  glUniformMatrix4fv(gbuffer_program_.uniform("u_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(view_projection));
  glUniform3fv(gbuffer_program_.uniform("u_camera_position"), 1, &camera.position.x);
  for (int k = 0; k < int(scene_->scene().objects.size()); ++k)
    scene_->draw_object(gbuffer_program_, k, RasterMesh::kSource);
}

void GeometryFieldMethod::render_tracing(const Camera& camera, Framebuffer& target,
                                         glm::vec2 jitter) {
  target.bind();
  glDisable(GL_DEPTH_TEST);
  glUseProgram(trace_program_.id());
  scene_->bind();
  glBindTextureUnit(gpu::UNIT_GBUFFER_POSITION, gbuffer_.texture(0));
  glBindTextureUnit(gpu::UNIT_GBUFFER_NORMAL, gbuffer_.texture(1));
  glBindTextureUnit(gpu::UNIT_GBUFFER_GEOMETRIC, gbuffer_.texture(2));
  glBindTextureUnit(gpu::UNIT_GBUFFER_ALBEDO, gbuffer_.texture(3));
  const auto u = [&](const char* name) { return trace_program_.uniform(name); };
  scene_->set_uniforms(trace_program_);
  set_camera_uniforms(trace_program_, camera, target.width(), target.height(), jitter);
  glUniform1i(u("u_mode"), int(settings_.mode));
  glUniform1i(u("u_self_reflection"), settings_.self_reflection ? 1 : 0);
  glUniform1i(u("u_max_depth"), settings_.max_depth);
  glUniform1f(u("u_min_weight"), settings_.min_weight);
  glUniform1i(u("u_max_rays"), settings_.max_rays);
  scene_->draw_fullscreen();
}

void GeometryFieldMethod::render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
                                 FrameStats* stats) {
  std::string error;
  if (scene_->assets().field_bits() != field_bits(settings_.field_bits) &&
      !scene_->require(needs(), error)) {  // --field-bits changed in the panel
    std::fprintf(stderr, "%s\n", error.c_str());
    settings_.field_bits = FieldBits(scene_->assets().field_bits() / 16);  // 8, 16, 32 -> 0, 1, 2
  }
  const Stopwatch clock;
  render_gbuffer(camera, target.width(), target.height(), jitter);
  const double gbuffer_ms = timed_ms(stats != nullptr, clock);
  render_tracing(camera, target, jitter);
  if (stats == nullptr)
    return;
  const double ms = timed_ms(true, clock);
  stats->milliseconds += ms;
  stats->add_part("G-buffer", gbuffer_ms);
  stats->add_part("tracing", ms - gbuffer_ms);
  long long traced = 0, rays = 0;
  for (const glm::vec4& h : target.read_hits()) {
    if (h.x >= 0.0f && scene_->scene().objects[size_t(h.x)].material.type != MaterialType::kDiffuse)
      ++traced;
    rays += (long long)(h.y);
  }
  stats->add_count("traced pixels", double(traced));
  stats->add_count("secondary rays", double(rays));
}

bool GeometryFieldMethod::reload_shaders_if_changed(std::string& error) {
  return reload_programs_if_changed({&gbuffer_program_, &trace_program_}, error);
}

std::string GeometryFieldMethod::summary(const FrameStats& per_sample) const {
  const double traced = per_sample.count("traced pixels");
  const double rays = per_sample.count("secondary rays");
  const double tracing_ms = per_sample.part_ms("tracing");
  if (rays <= 0.0)
    return "";
  char line[128];
  std::snprintf(line, sizeof(line),
                "%.2f secondary rays per traced pixel; tracing %.1f ns per traced pixel per bounce",
                traced > 0.0 ? rays / traced : 0.0, tracing_ms * 1e6 / rays);
  return line;
}

}  // namespace gfield
