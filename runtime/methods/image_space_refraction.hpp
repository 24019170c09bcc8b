#pragma once
// Image-space refraction through the screen-space maps of the refractors:
//   wyman2005    two-sided refraction (Wyman 2005): back-face depths and normals, the exit
//                distance interpolated between d_v and d_n (NAME.thickness.exr), one refraction
//                out of the back face.
//   davis-wyman  Davis & Wyman 2007: back and front normal/depth maps, nearby-geometry colour
//                and depth, binary search of frustum-clipped rays in the maps, total internal
//                reflection with 0..N internal bounces.
// Opaque surfaces are drawn and shaded as the reference tracer does, except that only analytic
// shapes cast shadows and mirrors reflect only the environment.

#include "runtime/method.hpp"
#include "runtime/methods/image_space_passes.hpp"
#include "runtime/render_target.hpp"

namespace gfield {

/// Where rays leaving a refractor look (Davis & Wyman, section 3 and Figure 1).
enum class ExitBackground {
  kDepthMap,  ///< binary search in the nearby-geometry colour/depth map, then the environment
  kAnalytic,  ///< exact intersection with the scene's opaque analytic shapes, then the environment
};

struct ImageSpaceRefractionSettings {
  int bounces = 3;               ///< davis-wyman: internal intersections (the paper shows 0..4)
  int iterations_first = 8;      ///< binary-search steps on the first transmitted ray
  int iterations_later = 5;      ///< on later rays
  int exit_iterations = 8;       ///< in the nearby-geometry map
  bool back_only_later = false;  ///< later bounces search the back-face map only
  /// Side of the intermediate buffers as a fraction of the picture's (0.25: 1/16 of the pixels).
  float buffer_scale = 1.0f;
  ExitBackground background = ExitBackground::kDepthMap;
  float min_alignment = 0.98f;  ///< cosine below which a depth-map candidate is a miss
};

class ImageSpaceRefractionMethod : public Method {
 public:
  /// `davis_wyman`: Davis & Wyman 2007; else Wyman 2005.
  explicit ImageSpaceRefractionMethod(bool davis_wyman) : davis_wyman_(davis_wyman) {}
  MethodInfo info() const override;
  std::vector<MethodOption> options() override;
  /// wyman2005 also needs the d_n map of every dielectric mesh.
  bool load(GpuScene& scene, const std::filesystem::path& shader_dir, std::string& error) override;
  /// Reports the part "screen maps". The maps are drawn at the pixel centres, the final pass at
  /// the sample offset.
  void render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
              FrameStats* stats) override;
  bool reload_shaders_if_changed(std::string& error) override;

  ImageSpaceRefractionSettings& settings() { return settings_; }

 private:
  void render_maps(const Camera& camera, int width, int height);
  void render_surface_map(RenderTarget& map, const ImageSpaceView& view, int facing);
  void render_nearby_map(RenderTarget& map, const ImageSpaceView& view);
  void set_refraction_uniforms() const;

  bool davis_wyman_;
  ImageSpaceRefractionSettings settings_;
  ImageSpacePasses passes_;
  ShaderProgram surfaces_program_;
  ShaderProgram refract_program_;
  RenderTarget back_, front_, nearby_;
};

}  // namespace gfield
