#pragma once
// Cube-map methods, the classic baselines of the geometry field:
//   cubemap  Hurley, "Approximating Refraction": the scene around each refractor (and mirror)
//            rendered into a cube map from its centre; one refraction by the article's
//            per-vertex vector or per fragment by Snell's law; Fresnel blending; reflection
//            beyond the critical angle.
//   envmap   the same cube maps looked up with the reflection vector for every non-diffuse
//            object: environment-mapped reflection (Blinn & Newell 1976) for mirror scenes.
// The opaque objects are drawn and shaded as the reference tracer does, except that only
// analytic shapes cast shadows and mirrors reflect through their cube map only.

#include <vector>

#include "runtime/method.hpp"
#include "runtime/methods/image_space_passes.hpp"

namespace gfield {

struct CubeMapSettings {
  int cube_size = 256;      ///< texels per cube face
  bool per_vertex = false;  ///< Hurley's interpolated per-vertex vector instead of Snell per pixel
  bool fresnel = false;     ///< blend in the Fresnel-weighted reflection
};

class CubeMapMethod : public Method {
 public:
  /// `reflect_only`: envmap (every object reflects); else cubemap.
  explicit CubeMapMethod(bool reflect_only) : reflect_only_(reflect_only) {}
  MethodInfo info() const override;
  std::vector<MethodOption> options() override;
  bool load(GpuScene& scene, const std::filesystem::path& shader_dir, std::string& error) override;
  /// Reports the part "cube maps".
  void render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
              FrameStats* stats) override;
  bool reload_shaders_if_changed(std::string& error) override;

  CubeMapSettings& settings() { return settings_; }

 private:
  struct CubeMap {
    GlTexture texture;
    GlRenderbuffer depth;
    int size = 0;
  };
  /// Objects drawn through their cube map: dielectrics, and mirrors.
  bool uses_cube(int object) const;
  void render_cube_map(int object, int size);

  bool reflect_only_;
  CubeMapSettings settings_;
  ImageSpacePasses passes_;
  ShaderProgram surface_program_;
  GlFramebuffer cube_framebuffer_;
  std::vector<CubeMap> cubes_;  ///< per object (only those that use one are allocated)
};

}  // namespace gfield
