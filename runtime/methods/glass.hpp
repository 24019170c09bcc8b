#pragma once
// The glass method (Mukai, Makino & Chang 2013; docs/glass.md): diffuse objects seen through one
// parallel glass plate (a "slab") or one hollow glass cylinder, without tracing rays through the
// glass per pixel:
//   1. depth peeling of the glass's triangles gives, per pixel, the sequence of glass surfaces
//      the eye line crosses (up to 4), hence its refraction class;
//   2. the opaque objects (meshes as the mesh files, analytic shapes tessellated) are drawn once
//      per refraction class present, every vertex moved in the vertex shader to where the eye
//      sees it along that class's path (shaders/lib/glass_displacement.glsl: the plate's equation
//      5 with equations 4 and 2; the cylinder's four, two or verge refractions with the sequence
//      of equations 6-8);
//   3. each pixel takes the image of its class; on top, Fresnel transmittance and reflection at
//      the glass, and the environment through the glass.
// Shading as the reference tracer's diffuse shading; shadows of directional lights by shadow
// maps (point lights cast none).

#include <vector>

#include <glm/glm.hpp>

#include "gfield/gpu_contract.hpp"
#include "runtime/method.hpp"
#include "runtime/methods/glass_geometry.hpp"
#include "runtime/render_target.hpp"

namespace gfield {

struct GlassSettings {
  /// Longest triangle edge when tessellating analytic shapes, as a fraction of the scene's
  /// extent (meshes are drawn as they are).
  float max_edge = 1.0f / 160.0f;
  bool fresnel = true;  ///< transmittance and reflection at the glass
  /// The hollow cylinder's verge (the band between its inner and outer silhouettes) traced per
  /// pixel to the analytic shapes and the environment instead of displaced: the verge's mapping
  /// folds (each point there is seen twice) and compresses too much for linear interpolation
  /// between vertices, but meshes are not seen on traced paths.
  bool trace_verge = false;
  int shadow_map_size = 2048;
};

class GlassMethod : public Method {
 public:
  MethodInfo info() const override;
  std::vector<MethodOption> options() override;
  /// The scene needs exactly one dielectric object, a slab or a hollow cylinder, and no mirrors.
  bool load(GpuScene& scene, const std::filesystem::path& shader_dir, std::string& error) override;
  /// Rebuilds the glass's triangles, the bounds and the shadow maps.
  void scene_changed() override;
  /// Reports the parts "peeling" and "class images" and the counts "class images" and "opaque
  /// vertices" (per frame).
  void render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
              FrameStats* stats) override;
  bool reload_shaders_if_changed(std::string& error) override;

  GlassSettings& settings() { return settings_; }
  /// Opaque vertices drawn per class image.
  long long vertex_count() const;

 private:
  /// One scene image per refraction class: a 2D-array colour texture and a depth buffer.
  struct ClassImages {
    GlTexture images;
    GlRenderbuffer depth;
    GlFramebuffer framebuffer;
    int width = 0, height = 0, layers = 0;
    void ensure(int w, int h, int class_layers);
  };

  bool find_glass(std::string& error);
  void update_geometry();
  void draw_opaque(const ShaderProgram& program) const;
  void render_shadow_maps();
  void set_light_uniforms(const ShaderProgram& program) const;
  void peel(const glm::mat4& view_projection, int width, int height);
  void draw_class_images(const Camera& camera, const std::vector<int>& classes,
                         const glm::mat4& view_projection, int layer_of_class[]);
  void set_class_uniforms(int refraction_class);
  void composite(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
                 const CameraFrustum& frustum, const int layer_of_class[]);

  GlassSettings settings_;
  GpuScene* scene_ = nullptr;
  int glass_object_ = -1;
  float extent_ = 1.0f;
  glm::vec3 lo_{0.0f}, hi_{0.0f};     ///< world bounds of the camera and the objects
  std::vector<GpuMesh> tessellated_;  ///< per object: analytic opaque shapes' triangles
  GlBuffer glass_buffer_;
  GlVertexArray glass_vertex_array_;
  GLsizei glass_vertex_count_ = 0;
  GlTexture shadow_maps_;
  GlFramebuffer shadow_framebuffer_;
  std::vector<glm::mat4> light_view_projection_;
  ShaderProgram peel_program_;
  ShaderProgram scene_program_;
  ShaderProgram shadow_program_;
  ShaderProgram composite_program_;
  RenderTarget layers_[gpu::GLASS_LAYERS];  ///< the peeled glass surfaces
  ClassImages class_images_;
  bool timed_ = false;        ///< the frame being drawn is timed (glFinish between passes)
  double peel_ms_ = 0.0;      ///< of the last timed frame
  double peel_gpu_ms_ = 0.0;  ///< its GPU time
};

}  // namespace gfield
