#include "runtime/methods/image_space_refraction.hpp"

#include <algorithm>
#include <cmath>

#include "gfield/gpu_contract.hpp"
#include "gfield/stopwatch.hpp"
#include "runtime/scene_assets.hpp"

namespace gfield {
namespace {

bool is_dielectric(const GpuScene& scene, int object) {
  return scene.scene().objects[size_t(object)].material.type == MaterialType::kDielectric;
}

}  // namespace

MethodInfo ImageSpaceRefractionMethod::info() const {
  return davis_wyman_ ? MethodInfo{"davis-wyman", "davis-wyman (TIR, Davis & Wyman 2007)"}
                      : MethodInfo{"wyman2005", "wyman2005 (two-sided, Wyman 2005)"};
}

std::vector<MethodOption> ImageSpaceRefractionMethod::options() {
  ImageSpaceRefractionSettings& s = settings_;
  std::vector<MethodOption> options = {
      int_option("exit-iterations", "steps, nearby geometry",
                 "binary-search steps in the nearby-geometry map", &s.exit_iterations, 0, 32),
      float_option("buffer-scale", "buffer scale",
                   "side of the intermediate buffers as a fraction of the picture's",
                   &s.buffer_scale, 0.0625f, 1.0f),
      choice_option("background", "leaving rays",
                    "where leaving rays look: depth-map (nearby geometry) or analytic shapes",
                    &s.background, {"depth-map", "analytic"}),
      float_option("min-alignment", "min alignment",
                   "cosine below which a depth-map candidate counts as a miss", &s.min_alignment,
                   -1.0f, 1.0f),
  };
  if (!davis_wyman_)
    return options;
  options.insert(
      options.begin(),
      {int_option("bounces", "bounces", "davis-wyman: internal bounces (0-4 in the paper)",
                  &s.bounces, 0, 16),
       int_option("iterations-first", "steps, first ray",
                  "davis-wyman: binary-search steps on the first transmitted ray",
                  &s.iterations_first, 0, 32),
       int_option("iterations-later", "steps, later rays",
                  "davis-wyman: binary-search steps on later rays", &s.iterations_later, 0, 32),
       flag_option("back-only-later", "back faces only after the first",
                   "davis-wyman: later bounces search the back faces only (the paper's speed-up)",
                   &s.back_only_later)});
  return options;
}

bool ImageSpaceRefractionMethod::load(GpuScene& scene, const std::filesystem::path& shader_dir,
                                      std::string& error) {
  const char* refract = davis_wyman_ ? "davis_wyman_refract.frag" : "wyman2005_refract.frag";
  // wyman2005 reads d_n: made on demand, as the other assets (runtime/scene_assets.hpp).
  return (davis_wyman_ || build_thickness_maps(scene.scene(), error)) &&
         passes_.load(scene, shader_dir, error) &&
         (davis_wyman_ || passes_.check_thickness_maps(error)) &&
         surfaces_program_.build(
             shader_dir, {"image_space_object.vert", "image_space_surfaces.frag"}, "", error) &&
         refract_program_.build(shader_dir, {"image_space_object.vert", refract}, "", error);
}

void ImageSpaceRefractionMethod::render_surface_map(RenderTarget& map, const ImageSpaceView& view,
                                                    int facing) {
  map.resize(view.width, view.height, {GL_RGBA32F}, GL_DEPTH_COMPONENT32F);
  map.bind();
  const float clear[4] = {0.0f, 0.0f, 0.0f, gpu::IS_FAR};
  glClearBufferfv(GL_COLOR, 0, clear);
  glClear(GL_DEPTH_BUFFER_BIT);
  passes_.begin(surfaces_program_, view);
  glUniform1i(surfaces_program_.uniform("u_facing"), facing);
  for (int k = 0; k < int(passes_.scene().scene().objects.size()); ++k)
    if (is_dielectric(passes_.scene(), k))
      passes_.draw_object(surfaces_program_, k);
}

void ImageSpaceRefractionMethod::render_nearby_map(RenderTarget& map, const ImageSpaceView& view) {
  map.resize(view.width, view.height, {GL_RGBA32F}, GL_DEPTH_COMPONENT32F);
  map.bind();
  const float clear[4] = {0.0f, 0.0f, 0.0f, gpu::IS_FAR};
  glClearBufferfv(GL_COLOR, 0, clear);
  glClear(GL_DEPTH_BUFFER_BIT);
  passes_.begin(passes_.forward(), view);
  glUniform1i(passes_.forward().uniform("u_alpha_is_coverage"), 0);
  for (int k = 0; k < int(passes_.scene().scene().objects.size()); ++k)
    if (!is_dielectric(passes_.scene(), k))
      passes_.draw_object(passes_.forward(), k);
}

void ImageSpaceRefractionMethod::render_maps(const Camera& camera, int width, int height) {
  // The maps at the buffer resolution, at the pixel centres (not offset by the sample).
  ImageSpaceView small = passes_.camera_view(camera, width, height, glm::vec2(0.0f));
  small.width = std::max(1, int(std::lround(float(width) * settings_.buffer_scale)));
  small.height = std::max(1, int(std::lround(float(height) * settings_.buffer_scale)));
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  render_surface_map(back_, small, -1);
  if (davis_wyman_)
    render_surface_map(front_, small, 1);
  if (settings_.background == ExitBackground::kDepthMap)
    render_nearby_map(nearby_, small);
}

void ImageSpaceRefractionMethod::set_refraction_uniforms() const {
  const auto u = [&](const char* name) { return refract_program_.uniform(name); };
  const ImageSpaceRefractionSettings& s = settings_;
  glUniform1i(u("u_facing"), 1);
  if (davis_wyman_) {  // its searches of the two maps (wyman2005 reads the back faces once)
    glUniform1i(u("u_bounces"), std::max(0, s.bounces));
    glUniform1i(u("u_iterations_first"), std::max(0, s.iterations_first));
    glUniform1i(u("u_iterations_later"), std::max(0, s.iterations_later));
    glUniform1i(u("u_back_only_later"), s.back_only_later ? 1 : 0);
  }
  glUniform1i(u("u_exit_iterations"), std::max(0, s.exit_iterations));
  glUniform1i(u("u_background"), int(s.background));
  glUniform1f(u("u_min_alignment"), s.min_alignment);
  glUniform1f(u("u_offset"), 1e-3f * passes_.scene().extent());
  glBindTextureUnit(gpu::UNIT_BACK, back_.texture(0));
  glBindTextureUnit(gpu::UNIT_FRONT, davis_wyman_ ? front_.texture(0) : 0);
  glBindTextureUnit(gpu::UNIT_NEARBY, nearby_.width() > 0 ? nearby_.texture(0) : 0);
}

void ImageSpaceRefractionMethod::render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
                                        FrameStats* stats) {
  PassClock clock(stats != nullptr);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  render_maps(camera, target.width(), target.height());
  const double pass_ms = clock.read();
  const ImageSpaceView view = passes_.camera_view(camera, target.width(), target.height(), jitter);
  target.bind();
  const GpuScene& scene = passes_.scene();
  passes_.draw_background_and_opaque(view, [&](int k) { return !is_dielectric(scene, k); });
  passes_.begin(refract_program_, view);
  set_refraction_uniforms();
  for (int k = 0; k < int(scene.scene().objects.size()); ++k)
    if (is_dielectric(scene, k))
      passes_.draw_object(refract_program_, k);
  add_frame_time(stats, clock, "screen maps", pass_ms, clock.gpu_ms(0));
}

bool ImageSpaceRefractionMethod::reload_shaders_if_changed(std::string& error) {
  std::vector<ShaderProgram*> programs = passes_.programs();
  programs.push_back(&surfaces_program_);
  programs.push_back(&refract_program_);
  return reload_programs_if_changed(programs, error);
}

}  // namespace gfield
