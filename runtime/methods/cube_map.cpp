#include "runtime/methods/cube_map.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "gfield/gpu_contract.hpp"
#include "gfield/stopwatch.hpp"

namespace gfield {

MethodInfo CubeMapMethod::info() const {
  return reflect_only_ ? MethodInfo{"envmap", "envmap (cube-map reflection, Blinn & Newell)"}
                       : MethodInfo{"cubemap", "cubemap (Hurley, Approximating Refraction)"};
}

std::vector<MethodOption> CubeMapMethod::options() {
  return {
      int_option("cube-size", "cube size", "cubemap/envmap: texels per cube face",
                 &settings_.cube_size, 8, 4096),
      flag_option("per-vertex", "per-vertex vector (Hurley)",
                  "cubemap: Hurley's per-vertex refraction vector (default: Snell per fragment)",
                  &settings_.per_vertex),
      flag_option("fresnel", "Fresnel", "cubemap: blend in the Fresnel reflection",
                  &settings_.fresnel),
  };
}

bool CubeMapMethod::load(GpuScene& scene, const std::filesystem::path& shader_dir,
                         std::string& error) {
  cube_framebuffer_.make();
  return passes_.load(scene, shader_dir, error) &&
         surface_program_.build(shader_dir, {"image_space_object.vert", "cubemap_surface.frag"}, "",
                                error);
}

bool CubeMapMethod::uses_cube(int object) const {
  const Material& m = passes_.scene().scene_object(object).material;
  return m.type == MaterialType::kDielectric || m.type == MaterialType::kMirror;
}

void CubeMapMethod::render_cube_map(int object, int size) {
  const GpuScene& scene = passes_.scene();
  CubeMap& cube = cubes_[size_t(object)];
  if (!cube.texture || cube.size != size) {
    cube.texture.make(GL_TEXTURE_CUBE_MAP);
    glTextureStorage2D(cube.texture.id(), 1, GL_RGBA16F, size, size);
    glTextureParameteri(cube.texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(cube.texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    cube.depth.make();
    glNamedRenderbufferStorage(cube.depth.id(), GL_DEPTH_COMPONENT32F, size, size);
    cube.size = size;
  }
  glm::vec3 lo, hi;
  scene.object_world_bounds(object, lo, hi);
  const glm::vec3 centre = 0.5f * (lo + hi);
  // OpenGL cube faces +X, -X, +Y, -Y, +Z, -Z: view direction and up of each.
  const glm::vec3 directions[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  const glm::vec2 range = depth_range(centre, scene, 1.0f / std::sqrt(3.0f), object);
  const float near_plane = range.x, far_plane = range.y;
  const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, near_plane, far_plane);
  ImageSpaceView view;
  view.position = centre;
  view.tan_half = glm::vec2(1.0f);
  view.near_far = glm::vec2(near_plane, far_plane);
  view.width = view.height = size;
  const GLuint framebuffer = cube_framebuffer_.id();
  glNamedFramebufferRenderbuffer(framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 cube.depth.id());
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size, size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  for (int face = 0; face < 6; ++face) {
    glNamedFramebufferTextureLayer(framebuffer, GL_COLOR_ATTACHMENT0, cube.texture.id(), 0, face);
    const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, clear);
    glClear(GL_DEPTH_BUFFER_BIT);
    view.forward = directions[face];
    view.up = -ups[face];
    view.right = glm::cross(view.forward, view.up);
    view.view_projection = projection * glm::lookAt(centre, centre + directions[face], ups[face]);
    passes_.begin(passes_.forward(), view);
    glUniform1i(passes_.forward().uniform("u_alpha_is_coverage"), 1);
    for (int k = 0; k < int(scene.scene().objects.size()); ++k)
      if (k != object)
        passes_.draw_object(passes_.forward(), k);
  }
}

void CubeMapMethod::render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
                           FrameStats* stats) {
  PassClock clock(stats != nullptr);
  const int objects = int(passes_.scene().scene().objects.size());
  cubes_.resize(size_t(objects));
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  for (int k = 0; k < objects; ++k)
    if (uses_cube(k))
      render_cube_map(k, std::max(1, settings_.cube_size));
  const double pass_ms = clock.read();
  const ImageSpaceView view = passes_.camera_view(camera, target.width(), target.height(), jitter);
  target.bind();
  passes_.draw_background_and_opaque(view, [&](int k) { return !uses_cube(k); });
  passes_.begin(surface_program_, view);
  const auto u = [&](const char* name) { return surface_program_.uniform(name); };
  glUniform1i(u("u_facing"), 1);
  glUniform1i(u("u_reflect_only"), reflect_only_ ? 1 : 0);
  glUniform1i(u("u_per_vertex"), settings_.per_vertex ? 1 : 0);
  glUniform1i(u("u_fresnel"), settings_.fresnel ? 1 : 0);
  for (int k = 0; k < objects; ++k) {
    if (!uses_cube(k))
      continue;
    glBindTextureUnit(gpu::UNIT_CUBE, cubes_[size_t(k)].texture.id());
    passes_.draw_object(surface_program_, k);
  }
  add_frame_time(stats, clock, "cube maps", pass_ms, clock.gpu_ms(0));
}

bool CubeMapMethod::reload_shaders_if_changed(std::string& error) {
  std::vector<ShaderProgram*> programs = passes_.programs();
  programs.push_back(&surface_program_);
  return reload_programs_if_changed(programs, error);
}

}  // namespace gfield
