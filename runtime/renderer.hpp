#pragma once
// The geometry-field renderer (Li et al. 2006, section 3): a scene's objects rasterised into a
// G-buffer (mesh objects as their geometry-image grids, analytic shapes exactly through their
// bounding boxes), then one shading pass (shaders/field_trace.frag) that shades diffuse hits,
// and traces reflected and refracted rays through the geometry fields of the mesh objects and
// the exact analytic shapes, recursively up to a depth, with shadows and the environment as the
// reference tracer (`gfield render`) does.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gfield/field_lookup.hpp"
#include "gfield/image.hpp"
#include "gfield/scene.hpp"
#include "runtime/framebuffer.hpp"
#include "runtime/gpu_assets.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

struct RenderSettings {
  LookupMode mode = LookupMode::kRefined;
  /// Reflections/refractions after the camera ray; a path needing more ends black (as
  /// `gfield render --depth`).
  int max_depth = 10;
  /// Mesh objects also look up their own field (self-reflection, self-shadowing).
  bool self_reflection = true;
  /// Branches whose path weight falls below this are not traced.
  float min_weight = 0.005f;
  /// Secondary rays per pixel at most (the GPU has no unbounded recursion).
  int max_rays = 24;
  /// Samples per pixel on a stratified grid at the strata centres (1: the pixel centre).
  int samples_per_pixel = 1;
};

struct FrameStats {
  double milliseconds = 0.0;  ///< wall time of the frame (glFinish), all samples
  double gbuffer_milliseconds = 0.0;
  double trace_milliseconds = 0.0;
  long long traced_pixels = 0;   ///< pixels whose first hit is a mirror or a dielectric
  long long secondary_rays = 0;  ///< reflected/refracted rays traced (sum over pixels)
};

class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Loads the scene's geometry images, fields and environment, uploads them and builds the
  /// shaders from `shader_dir`. Needs a current GL 4.5 context. False with "FILE: problem" for
  /// missing or mismatched assets and FILE:LINE messages for shader errors.
  bool load(const Scene& scene, const std::filesystem::path& shader_dir, std::string& error);

  /// The scene being drawn; after changing objects, materials or lights call update_scene().
  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }
  void update_scene();

  /// Renders one frame of `camera` into `target` (its size), with a sample offset `jitter` in
  /// pixels from the pixel centres. With `stats`, reads the hit buffer back for the counts.
  void render(const Camera& camera, const RenderSettings& settings, Framebuffer& target,
              glm::vec2 jitter = glm::vec2(0.0f), FrameStats* stats = nullptr);

  /// Renders `width` x `height` of the scene's camera with settings.samples_per_pixel samples
  /// (averaged) and reads it back.
  Image render_image(int width, int height, const RenderSettings& settings,
                     FrameStats* stats = nullptr);

  /// Rebuilds the shaders when their files changed. True when rebuilt; `error` on failure (the
  /// old shaders stay).
  bool reload_shaders_if_changed(std::string& error);

  const GpuAssets& assets() const { return assets_; }
  /// Diagonal of all objects' bounds and the camera.
  float scene_extent() const { return extent_; }

 private:
  Scene scene_;
  GpuAssets assets_;
  std::vector<int> mesh_asset_;  ///< Scene::meshes index -> asset
  ShaderProgram gbuffer_program_;
  ShaderProgram trace_program_;
  GLuint gbuffer_textures_[3] = {0, 0, 0};  ///< position+object, normal+u, geometric+v
  GLuint gbuffer_fbo_ = 0;
  GLuint gbuffer_depth_ = 0;
  int gbuffer_width_ = 0, gbuffer_height_ = 0;
  GLuint objects_buffer_ = 0;
  GLuint lights_buffer_ = 0;
  GLuint environment_ = 0;
  GLuint proxy_vertex_array_ = 0;
  GLuint proxy_buffer_ = 0;
  GLuint empty_vertex_array_ = 0;
  float extent_ = 1.0f;
  bool ensure_gbuffer(int width, int height);
  void release_gbuffer();
};

}  // namespace gfield
