#pragma once
// The image-space methods of gfield-view (docs/image-space-refraction.md), the baselines the
// geometry-field renderer is measured against:
//   cubemap     Hurley, "Approximating Refraction": the scene around each refractor (and mirror)
//               rendered into a cube map from its centre; one refraction by the article's
//               per-vertex vector or per fragment; Fresnel blending; reflection beyond the
//               critical angle.
//   envmap      the same cube maps with the reflection vector for every non-diffuse object: the
//               classic environment-mapped reflection (Blinn & Newell 1976) for mirror scenes.
//   wyman2005   two-sided image-space refraction (Wyman 2005): back-face depths and normals, the
//               exit distance interpolated between d_v and d_n (NAME.thickness.exr), one
//               refraction out of the back face.
//   davis-wyman Davis & Wyman 2007: back and front normal/depth maps, nearby-geometry colour and
//               depth, binary search of frustum-clipped rays in the maps, total internal
//               reflection with 0..N internal bounces.
// Mesh objects are rasterised as their geometry-image grids (no geometry field is needed);
// analytic shapes exactly per fragment through their bounding boxes. Opaque surfaces are shaded
// as the reference tracer does, except that only analytic shapes cast shadows and mirrors outside
// the cube-map methods reflect only the environment.

#include <filesystem>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gfield/image.hpp"
#include "gfield/scene.hpp"
#include "runtime/framebuffer.hpp"
#include "runtime/gpu_assets.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

enum class ImageSpaceMethod { kCubeMap, kEnvMap, kWyman2005, kDavisWyman };

/// "cubemap", "envmap", "wyman2005", "davis-wyman" -> method; false for anything else.
bool parse_image_space_method(const std::string& name, ImageSpaceMethod& method);
const char* image_space_method_name(ImageSpaceMethod method);

/// Where rays leaving a refractor look (Davis & Wyman, section 3 and Figure 1).
enum class ExitBackground {
  kDepthMap,  ///< binary search in the nearby-geometry colour/depth map, then the environment
  kAnalytic,  ///< exact intersection with the scene's opaque analytic shapes, then the environment
};

struct ImageSpaceSettings {
  ImageSpaceMethod method = ImageSpaceMethod::kDavisWyman;
  // cubemap / envmap
  int cube_size = 256;      ///< texels per cube face
  bool per_vertex = false;  ///< Hurley's interpolated per-vertex vector instead of Snell per pixel
  bool fresnel = false;     ///< blend in the Fresnel-weighted reflection
  // wyman2005 / davis-wyman
  int bounces = 3;               ///< davis-wyman: internal intersections (the paper shows 0..4)
  int iterations_first = 8;      ///< binary-search steps on the first transmitted ray
  int iterations_later = 5;      ///< on later rays
  int exit_iterations = 8;       ///< in the nearby-geometry map
  bool back_only_later = false;  ///< later bounces search the back-face map only
  /// Side of the intermediate buffers as a fraction of the picture's (0.25: 1/16 of the pixels).
  float buffer_scale = 1.0f;
  ExitBackground background = ExitBackground::kDepthMap;
  float min_alignment = 0.98f;  ///< cosine below which a depth-map candidate is a miss
  /// Stratified samples per pixel of render_image (the final pass is drawn once per sample with
  /// a sub-pixel offset; the screen maps and cube maps are not offset).
  int samples_per_pixel = 1;
};

struct ImageSpaceStats {
  double milliseconds = 0.0;       ///< wall time of the frame (glFinish)
  double pass_milliseconds = 0.0;  ///< of it, cube maps / depth and nearby-geometry maps
};

class ImageSpaceRenderer {
 public:
  ImageSpaceRenderer();
  ~ImageSpaceRenderer();
  ImageSpaceRenderer(const ImageSpaceRenderer&) = delete;
  ImageSpaceRenderer& operator=(const ImageSpaceRenderer&) = delete;

  /// Loads the geometry images of the scene's meshes (and their thickness maps where present),
  /// the environment, and builds the shaders. Needs a current GL 4.5 context. False with
  /// "FILE: problem".
  bool load(const Scene& scene, const std::filesystem::path& shader_dir, std::string& error);

  /// False with a message when `method` cannot run on this scene (wyman2005 needs the thickness
  /// map of every dielectric mesh).
  bool supports(ImageSpaceMethod method, std::string& error) const;

  /// The scene being drawn; after changing objects, materials or lights call update_scene().
  Scene& scene() { return scene_; }
  void update_scene();

  /// Renders one frame of `camera` into `target` (its size), its final pass with a sample offset
  /// `jitter` in pixels (x right, y down) from the pixel centres.
  void render(const Camera& camera, const ImageSpaceSettings& settings, Framebuffer& target,
              glm::vec2 jitter = glm::vec2(0.0f), ImageSpaceStats* stats = nullptr);
  /// Renders width x height of the scene's camera with settings.samples_per_pixel samples per
  /// pixel and reads it back (linear radiance, rows top to bottom).
  Image render_image(int width, int height, const ImageSpaceSettings& settings,
                     ImageSpaceStats* stats = nullptr);

  bool reload_shaders_if_changed(std::string& error);

 private:
  struct ScreenMap {
    GLuint texture = 0;
    GLuint framebuffer = 0;
    GLuint depth = 0;
    int width = 0;
    int height = 0;
  };
  struct CubeMap {
    GLuint texture = 0;
    GLuint depth = 0;
    int size = 0;
  };
  struct View;

  bool ensure_map(ScreenMap& map, int width, int height);
  void release_map(ScreenMap& map);
  bool ensure_cube(CubeMap& cube, int size);
  void set_common_uniforms(const ShaderProgram& program, const View& view) const;
  void draw_object(const ShaderProgram& program, int object) const;
  void render_cube_map(int object, int size);
  void render_surface_map(ScreenMap& map, const View& view, int facing);
  void render_nearby_map(ScreenMap& map, const View& view);
  /// Eye-depth range [near, far] of the bounds of the dielectric objects (or of all the others),
  /// within the view's near and far planes: the depth range of the binary searches' frustums.
  glm::vec2 eye_depth_range(const View& view, bool dielectrics) const;

  Scene scene_;
  GpuAssets assets_;
  std::vector<int> thickness_layer_;  ///< Scene::meshes index -> layer, -1 when missing
  std::vector<std::string> thickness_missing_;
  GLuint thickness_ = 0;
  GLuint environment_ = 0;
  GLuint objects_buffer_ = 0;
  GLuint lights_buffer_ = 0;
  GLuint proxy_buffer_ = 0;
  GLuint proxy_vertex_array_ = 0;
  GLuint empty_vertex_array_ = 0;
  GLuint cube_framebuffer_ = 0;
  float extent_ = 1.0f;
  ShaderProgram forward_program_;
  ShaderProgram surfaces_program_;
  ShaderProgram background_program_;
  ShaderProgram cubemap_program_;
  ShaderProgram wyman2005_program_;
  ShaderProgram davis_wyman_program_;
  ScreenMap back_, front_, nearby_;
  std::vector<CubeMap> cubes_;  ///< per object (only those that use one are allocated)
};

}  // namespace gfield
