#pragma once
// The `glass` method of gfield-view (Mukai, Makino & Chang 2013; docs/glass.md): diffuse objects
// seen through one parallel glass plate (a "slab") or one hollow glass cylinder, without tracing
// rays through the glass per pixel:
//   1. depth peeling of the glass's triangles gives, per pixel, the sequence of glass surfaces
//      the eye line crosses (up to 4), hence its refraction class;
//   2. the opaque objects (meshes as triangles, analytic shapes tessellated) are drawn once per
//      refraction class present, every vertex moved in the vertex shader to where the eye sees it
//      along that class's path (shaders/lib/glass_displacement.glsl: the plate's equation 5 with
//      equations 4 and 2; the cylinder's four, two or verge refractions with the sequence of
//      equations 6-8);
//   3. each pixel takes the image of its class; on top, Fresnel transmittance and reflection at
//      the glass, and the environment through the glass.
// Shading as the reference tracer's diffuse shading; shadows of directional lights by shadow
// maps (point lights cast none).

#include <filesystem>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gfield/image.hpp"
#include "gfield/scene.hpp"
#include "runtime/framebuffer.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

struct GlassSettings {
  /// Longest triangle edge when tessellating analytic shapes, as a fraction of the scene's
  /// extent (meshes are drawn as they are).
  float max_edge = 1.0f / 160.0f;
  int samples_per_pixel = 1;  ///< stratified grid at the strata centres, as Renderer
  bool fresnel = true;        ///< transmittance and reflection at the glass
  /// The hollow cylinder's verge (the band between its inner and outer silhouettes) traced per
  /// pixel to the analytic shapes and the environment instead of displaced: the verge's mapping
  /// folds (each point there is seen twice) and compresses too much for linear interpolation
  /// between vertices, but meshes are not seen on traced paths.
  bool trace_verge = false;
  int shadow_map_size = 2048;
};

struct GlassStats {
  double milliseconds = 0.0;  ///< wall time of the frame(s) (glFinish)
  double peel_milliseconds = 0.0;
  double scene_milliseconds = 0.0;  ///< the class images (vertex displacement + shading)
  int class_images = 0;             ///< scene images drawn (per sample)
  long long vertices = 0;           ///< opaque vertices drawn per class image
};

/// Refraction classes: 0 none; slab: 1 + the face pair (Z, X, Y) the line enters; hollow
/// cylinder: 4 + GD_PATH_* (both walls, verge, front wall, back wall).
inline constexpr int kGlassClasses = 8;

class GlassRenderer {
 public:
  GlassRenderer();
  ~GlassRenderer();
  GlassRenderer(const GlassRenderer&) = delete;
  GlassRenderer& operator=(const GlassRenderer&) = delete;

  /// Loads the meshes, tessellates the analytic shapes, uploads the environment and builds the
  /// shaders. The scene needs exactly one dielectric object, a slab or a hollow cylinder, and
  /// no mirrors. Needs a current GL 4.5 context. False with "FILE: problem".
  bool load(const Scene& scene, const std::filesystem::path& shader_dir,
            const GlassSettings& settings, std::string& error);

  const Scene& scene() const { return scene_; }

  /// Renders one frame of `camera` into `target` with a sample offset `jitter` (pixels).
  void render(const Camera& camera, const GlassSettings& settings, Framebuffer& target,
              glm::vec2 jitter = glm::vec2(0.0f), GlassStats* stats = nullptr);
  /// Renders width x height of the scene's camera (settings.samples_per_pixel averaged).
  Image render_image(int width, int height, const GlassSettings& settings,
                     GlassStats* stats = nullptr);

  bool reload_shaders_if_changed(std::string& error);

  /// Opaque vertices drawn per class image.
  long long vertex_count() const;

 private:
  struct DrawObject {
    int object = -1;
    GLuint vertex_array = 0;
    GLuint buffer = 0;
    GLuint index_buffer = 0;
    GLsizei index_count = 0;
    GLsizei vertex_count = 0;
  };
  struct Target {
    GLuint texture = 0;
    GLuint framebuffer = 0;
    GLuint depth = 0;
  };

  void release_targets();
  bool ensure_targets(int width, int height, int class_layers);
  void render_shadow_maps();
  std::vector<int> classes_present(const Camera& camera, float aspect, bool trace_verge) const;

  Scene scene_;
  int glass_object_ = -1;
  std::vector<DrawObject> draws_;
  GLuint glass_buffer_ = 0;
  GLuint glass_vertex_array_ = 0;
  GLsizei glass_vertex_count_ = 0;
  GLuint environment_ = 0;
  GLuint shadow_maps_ = 0;
  GLuint shadow_framebuffer_ = 0;
  std::vector<glm::mat4> light_view_projection_;
  GLuint opaque_buffer_ = 0;
  int opaque_count_ = 0;
  GLuint empty_vertex_array_ = 0;
  float extent_ = 1.0f;
  glm::vec3 lo_{0.0f}, hi_{0.0f};  ///< world bounds of the opaque objects
  ShaderProgram peel_program_;
  ShaderProgram scene_program_;
  ShaderProgram shadow_program_;
  ShaderProgram composite_program_;
  Target layers_[4];
  GLuint class_images_ = 0;
  GLuint class_framebuffer_ = 0;
  GLuint class_depth_ = 0;
  int width_ = 0, height_ = 0, class_layers_ = 0;
};

}  // namespace gfield
