#pragma once
// The geometry-field method (Li et al. 2006, section 3): the scene's objects rasterised into a
// G-buffer (meshes as the mesh files themselves, analytic shapes exactly through their bounding
// boxes), then one tracing pass (shaders/lib/field_trace.glsl, as a fragment pass or a compute
// dispatch: methods/trace_pass.hpp) that shades diffuse hits and traces reflected and refracted
// rays through the geometry fields of the mesh objects and the exact analytic shapes,
// recursively up to a depth, with shadows and the environment as the reference tracer
// (`gfield render`) does.

#include <map>
#include <memory>

#include "gfield/field_lookup.hpp"
#include "runtime/method.hpp"
#include "runtime/methods/intersect_route.hpp"
#include "runtime/methods/trace_pass.hpp"
#include "runtime/render_target.hpp"
#include "runtime/shader_program.hpp"
#include "runtime/work_counters.hpp"

namespace gfield {

/// How rays meet the mesh objects: a lookup in their geometry field, exactly through a BVH of
/// their triangles, or each mesh the way the cost model says is cheaper for it
/// (methods/intersect_route.hpp). Meshes without a field always use their BVH.
enum class MeshIntersection { kField = 0, kBvh = 1, kAuto = 2 };

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
  MeshIntersection intersect = MeshIntersection::kField;
  /// The tracing pass: a compute dispatch, a full-screen fragment pass, or the faster of the two
  /// as measured on the first frames.
  TracePass pass = TracePass::kAuto;
  /// Count the work of lookups and traversals (work_counters.hpp) into the frame's stats: the
  /// counting build of the shading pass.
  bool count_work = false;
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
  /// Secondary rays per traced pixel and ns of tracing per ray; with count-work, fetches per
  /// lookup and BVH nodes per traversal.
  std::string summary(const FrameStats& per_sample) const override;
  /// Which mesh objects are traced how ("meshes by field: spot.obj; by BVH: torus.obj (no
  /// field)") and, on a line of its own, in which pass ("tracing pass: compute").
  std::string status() const override;
  std::vector<std::string> notes() const override;
  /// While --pass auto's trial runs.
  bool measuring() const override { return !pass_settled(); }

  GeometryFieldSettings& settings() { return settings_; }
  /// The tracing pass and why: "compute", or with --pass auto "compute (auto: 41.2 ms against
  /// fragment 55.0 ms)" (methods/trace_pass.hpp).
  std::string pass_status() const;
  /// False while --pass auto's trial still times the passes at the last frame's size.
  bool pass_settled() const;

 private:
  /// The assets this method needs (the fields at the settings' bits).
  AssetNeeds needs() const;
  /// --intersect auto's route for each mesh of the scene (methods/intersect_route.hpp).
  std::vector<Route> auto_routes() const;
  /// Sets the scene's per-mesh BVH routes for the current --intersect (all 0 unless auto) and
  /// loads the BVHs they need.
  bool route_meshes(std::string& error);
  void render_gbuffer(const Camera& camera, int width, int height, glm::vec2 jitter);
  /// False when the pass's program does not build (the message on stderr).
  bool render_tracing(const Camera& camera, Framebuffer& target, glm::vec2 jitter, TracePass pass);
  /// The pass this frame traces in: the setting's, or --pass auto's (restarting its trial for a
  /// new program or frame size).
  TracePass frame_pass(int width, int height);
  /// Loads what a changed setting needs (field bits, BVHs); false when it
  /// cannot (the message on stderr, the setting back to what works).
  bool follow_settings();
  /// The defines of the shading pass for the settings and the scene: GF_TRACE_MODE,
  /// GF_FIELD_MESHES, GF_BVH_MESHES (0: no mesh met that way), GF_FIELD_SHADOWS (0: no diffuse
  /// mesh traced by its field), GF_COUNT_WORK.
  std::string trace_defines() const;
  /// The tracing pass `pass` for trace_defines(), built on first use (null, the message on
  /// stderr, when it does not build).
  const ShaderProgram* trace_program(TracePass pass);

  GeometryFieldSettings settings_;
  GpuScene* scene_ = nullptr;
  std::filesystem::path shader_dir_;
  ShaderProgram gbuffer_program_;
  /// The tracing passes built for the settings and the scene (by pass, then trace_defines()),
  /// each on first use: on llvmpipe a shader runs every branch of its code under a mask, so the
  /// lookup modes and the ways of meeting meshes that a frame does not use are compiled out.
  std::map<std::string, std::unique_ptr<ShaderProgram>> trace_programs_;
  PassTrial pass_trial_;  ///< --pass auto's measurements
  WorkCounters work_;
  std::vector<char> routes_;  ///< the per-mesh BVH routes set in the scene (route_meshes)
  /// position + object, shading normal + u, geometric normal + v, albedo
  RenderTarget gbuffer_;
};

}  // namespace gfield
