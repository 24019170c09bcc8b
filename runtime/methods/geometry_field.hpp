#pragma once
// The geometry-field method (Li et al. 2006, section 3): the scene's objects rasterised into a
// G-buffer (meshes as the mesh files themselves, analytic shapes exactly through their bounding
// boxes), then one shading pass (shaders/field_trace.frag) that shades diffuse hits and traces
// reflected and refracted rays through the geometry fields of the mesh objects and the exact
// analytic shapes, recursively up to a depth, with shadows and the environment as the reference
// tracer (`gfield render`) does.

#include "gfield/field_lookup.hpp"
#include "runtime/method.hpp"
#include "runtime/render_target.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

/// Bits per uv component of the fields on the GPU (RG8, RG16, RG32F).
enum class FieldBits { k8 = 0, k16 = 1, k32 = 2 };
inline int field_bits(FieldBits bits) {
  return 8 << int(bits);
}

struct GeometryFieldSettings {
  LookupMode mode = LookupMode::kRefined;
  /// The fields' storage on the GPU: 8 bits keep the refined lookup within 0.05 points of the
  /// float field's hit/miss agreement (docs/runtime.md) at a quarter of its memory.
  FieldBits field_bits = FieldBits::k8;
  /// Reflections/refractions after the camera ray; a path needing more ends black (as
  /// `gfield render --depth`).
  int max_depth = 10;
  /// Mesh objects also look up their own field (self-reflection, self-shadowing).
  bool self_reflection = true;
  /// Branches whose path weight falls below this are not traced.
  float min_weight = 0.005f;
  /// Secondary rays per pixel at most (the GPU has no unbounded recursion).
  int max_rays = 24;
};

class GeometryFieldMethod : public Method {
 public:
  MethodInfo info() const override;
  std::vector<MethodOption> options() override;
  bool load(GpuScene& scene, const std::filesystem::path& shader_dir, std::string& error) override;
  /// Counts "traced pixels" (first hit a mirror or dielectric) and "secondary rays" into
  /// `stats` by reading the hit attachment back.
  void render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
              FrameStats* stats) override;
  bool reload_shaders_if_changed(std::string& error) override;
  /// Secondary rays per traced pixel and ns of tracing per ray.
  std::string summary(const FrameStats& per_sample) const override;

  GeometryFieldSettings& settings() { return settings_; }

 private:
  /// The assets this method needs (the fields at the settings' bits).
  AssetNeeds needs() const;
  void render_gbuffer(const Camera& camera, int width, int height, glm::vec2 jitter);
  void render_tracing(const Camera& camera, Framebuffer& target, glm::vec2 jitter);

  GeometryFieldSettings settings_;
  GpuScene* scene_ = nullptr;
  ShaderProgram gbuffer_program_;
  ShaderProgram trace_program_;
  /// position + object, shading normal + u, geometric normal + v, albedo
  RenderTarget gbuffer_;
};

}  // namespace gfield
