#include "runtime/methods/geometry_field.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include <glm/gtc/type_ptr.hpp>

#include "gfield/gpu_contract.hpp"
#include "gfield/stopwatch.hpp"

namespace gfield {
namespace {

std::vector<std::string> trace_stages(TracePass pass) {
  if (pass == TracePass::kCompute)
    return {"field_trace.comp"};
  return {"fullscreen.vert", "field_trace.frag"};
}

std::string trace_program_key(TracePass pass, const std::string& defines) {
  return std::string(trace_pass_name(pass)) + "\n" + defines;
}

/// The compute tracing pass over `target`: its colour and hits bound as images, one group per
/// tile of the program's group size, 2^bits groups (the tiles in bit-reversed order,
/// field_trace.comp).
void dispatch_tracing(const ShaderProgram& program, Framebuffer& target) {
  glBindImageTexture(gpu::IMAGE_TRACE_COLOR, target.color_texture(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  glBindImageTexture(gpu::IMAGE_TRACE_HITS, target.hits_texture(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  GLint group[3] = {1, 1, 1};
  glGetProgramiv(program.id(), GL_COMPUTE_WORK_GROUP_SIZE, group);
  const int columns = (target.width() + group[0] - 1) / group[0];
  const int tiles = columns * ((target.height() + group[1] - 1) / group[1]);
  int bits = 1;
  while ((1 << bits) < tiles)
    ++bits;
  const int x_bits = std::min(bits, 15);  // every GL takes 65535 groups a dimension
  glUniform1i(program.uniform("u_tile_columns"), columns);
  glUniform1i(program.uniform("u_tile_bits"), bits);
  glDispatchCompute(1u << x_bits, 1u << (bits - x_bits), 1);
  // What reads the frame next: drawing into it, sampling it, or reading it back.
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
}

}  // namespace

MethodInfo GeometryFieldMethod::info() const {
  return {"field", "geometry field (Li et al. 2006)"};
}

std::vector<MethodOption> GeometryFieldMethod::options() {
  GeometryFieldSettings& s = settings_;
  return {
      choice_option("mode", "lookup", "Geometry-field lookup: nearest, linear or refined", &s.mode,
                    {"nearest", "linear", "refined"}),
      choice_option("field-bits", "field bits",
                    "Bits per uv component of the fields on the GPU: 8 (RG8), 16 (RG16) or 32 "
                    "(RG32F)",
                    &s.field_bits, {"8", "16", "32"}),
      int_option("depth", "depth",
                 "Reflections/refractions after the camera ray (as gfield render --depth)",
                 &s.max_depth, 0, 64),
      flag_option("no-self-reflection", "self-reflection",
                  "Objects do not look up their own field (no self-reflection, no self-shadows)",
                  &s.self_reflection, false),
      float_option("min-weight", "min weight", "Branches below this weight are dropped",
                   &s.min_weight, 0.0f, 1.0f),
      int_option("max-rays", "max rays / pixel", "Secondary rays per pixel at most", &s.max_rays, 1,
                 256),
      choice_option("intersect", "intersect meshes",
                    "How rays meet meshes: field (a geometry-field lookup), bvh (their triangles, "
                    "exactly, through a BVH) or auto (each mesh the cheaper way by a cost model: "
                    "docs/runtime.md); a mesh without a field always by its BVH",
                    &s.intersect, {"field", "bvh", "auto"}),
      choice_option("pass", "tracing pass",
                    "The tracing pass: compute (a dispatch: every shader core of a data-centre "
                    "GPU), fragment (a full-screen pass) or auto (the faster of the two, timed on "
                    "the first frames); the pictures are the same",
                    &s.pass, {"auto", "compute", "fragment"}),
      flag_option("count-work", "count work",
                  "Count field lookups, texel fetches, Newton steps and BVH nodes (--bench prints "
                  "them per sample)",
                  &s.count_work),
  };
}

std::vector<Route> GeometryFieldMethod::auto_routes() const {
  const Scene& scene = scene_->scene();
  const std::vector<GpuAsset>& assets = scene_->assets().assets();
  std::vector<RouteInputs> meshes(scene.meshes.size());
  for (size_t m = 0; m < meshes.size() && m < assets.size(); ++m) {
    meshes[m].triangles = size_t(assets[m].source.index_count) / 3;
    meshes[m].has_field = assets[m].samples_per_side > 0;
  }
  for (const SceneObject& o : scene.objects)
    if (o.shape.type == ShapeType::kMesh && o.material.type == MaterialType::kDielectric)
      meshes[size_t(o.shape.mesh)].dielectric = true;
  std::vector<Route> routes;
  for (const RouteInputs& mesh : meshes)
    routes.push_back(auto_route(mesh));
  return routes;
}

bool GeometryFieldMethod::route_meshes(std::string& error) {
  std::vector<char> by_bvh(scene_->scene().meshes.size(), 0);
  if (settings_.intersect == MeshIntersection::kAuto) {
    const std::vector<Route> routes = auto_routes();
    for (size_t m = 0; m < routes.size(); ++m)
      by_bvh[m] = routes[m].bvh ? 1 : 0;
  }
  if (by_bvh == routes_)
    return true;
  routes_ = by_bvh;
  scene_->set_bvh_routes(std::move(by_bvh));
  return scene_->require(needs(), error);  // the BVHs the routes need
}

AssetNeeds GeometryFieldMethod::needs() const {
  AssetNeeds needs;
  needs.fields = true;
  needs.optional_fields = true;  // a mesh without them is traced through its BVH
  needs.field_bits = field_bits(settings_.field_bits);
  needs.source_meshes = true;  // the G-buffer holds the surfaces the reference tracer sees
  needs.bvhs = settings_.intersect == MeshIntersection::kBvh;
  for (size_t m = 0; m < scene_->scene().meshes.size(); ++m) {
    const MeshAsset& mesh = scene_->scene().meshes[m];
    needs.bvhs = needs.bvhs || mesh.geometry_image.empty() || mesh.geometry_field.empty() ||
                 scene_->bvh_route(int(m));
  }
  return needs;
}

bool GeometryFieldMethod::load(GpuScene& scene, const std::filesystem::path& shader_dir,
                               std::string& error) {
  scene_ = &scene;
  shader_dir_ = shader_dir;
  trace_programs_.clear();
  pass_trial_ = {};
  if (!scene.require(needs(), error) || !route_meshes(error) ||
      !gbuffer_program_.build(shader_dir, {"gbuffer.vert", "gbuffer.frag"}, "", error))
    return false;
  for (TracePass pass : {TracePass::kCompute, TracePass::kFragment}) {
    if (settings_.pass != TracePass::kAuto && pass != settings_.pass)
      continue;
    auto program = std::make_unique<ShaderProgram>();
    if (!program->build(shader_dir, trace_stages(pass), trace_defines(), error))
      return false;
    trace_programs_[trace_program_key(pass, trace_defines())] = std::move(program);
  }
  return true;
}

std::string GeometryFieldMethod::trace_defines() const {
  const std::vector<GpuAsset>& assets = scene_->assets().assets();
  auto by_its_field = [&](int m) {
    return assets[size_t(m)].samples_per_side > 0 &&
           settings_.intersect != MeshIntersection::kBvh && !scene_->bvh_route(m);
  };
  bool by_field = false, by_bvh = false, field_shadows = false;
  for (size_t m = 0; m < assets.size(); ++m) {
    const bool field = by_its_field(int(m));
    by_field = by_field || field;
    by_bvh = by_bvh || !field;
  }
  for (const SceneObject& o : scene_->scene().objects) {
    field_shadows =
        field_shadows || (o.shape.type == ShapeType::kMesh && o.shape.mesh >= 0 &&
                          o.material.type == MaterialType::kDiffuse && by_its_field(o.shape.mesh));
  }
  const bool cached_entries = scene_->scene().objects.size() <= size_t(gpu::SCENE_CACHED_ENTRIES);
  return "#define GF_TRACE_MODE " + std::to_string(int(settings_.mode)) +
         "\n#define GF_FIELD_MESHES " + (by_field ? "1" : "0") + "\n#define GF_BVH_MESHES " +
         (by_bvh ? "1" : "0") + "\n#define GF_FIELD_SHADOWS " + (field_shadows ? "1" : "0") +
         "\n#define GF_CACHED_ENTRIES " + (cached_entries ? "1" : "0") + "\n" +
         (settings_.count_work ? "#define GF_COUNT_WORK 1\n" : "");
}

const ShaderProgram* GeometryFieldMethod::trace_program(TracePass pass) {
  const std::string defines = trace_defines();
  const std::string key = trace_program_key(pass, defines);
  std::unique_ptr<ShaderProgram>& program = trace_programs_[key];
  if (!program) {
    auto built = std::make_unique<ShaderProgram>();
    std::string error;
    if (!built->build(shader_dir_, trace_stages(pass), defines, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      trace_programs_.erase(key);
      return nullptr;
    }
    program = std::move(built);
  }
  return program.get();
}

bool GeometryFieldMethod::follow_settings() {
  std::string error;
  const AssetNeeds wanted = needs();
  const GpuAssets& assets = scene_->assets();
  const bool bvhs_loaded = std::any_of(assets.assets().begin(), assets.assets().end(),
                                       [](const GpuAsset& a) { return a.bvh_root >= 0; });
  if ((assets.field_bits() != wanted.field_bits || (wanted.bvhs && !bvhs_loaded)) &&
      !scene_->require(wanted, error)) {  // --field-bits or --intersect changed in the panel
    std::fprintf(stderr, "%s\n", error.c_str());
    settings_.field_bits = FieldBits(assets.field_bits() / 16);  // 8, 16, 32 -> 0, 1, 2
    settings_.intersect = MeshIntersection::kField;
    return false;
  }
  if (!route_meshes(error)) {  // --intersect auto chosen or left in the panel
    std::fprintf(stderr, "%s\n", error.c_str());
    return false;
  }
  return true;
}

void GeometryFieldMethod::render_gbuffer(const Camera& camera, int width, int height,
                                         glm::vec2 jitter) {
  gbuffer_.resize(width, height, {GL_RGBA32F, GL_RGBA32F, GL_RGBA32F, GL_RGBA32F},
                  GL_DEPTH_COMPONENT32F);
  gbuffer_.bind();
  const float clear_position[4] = {0.0f, 0.0f, 0.0f, -1.0f};
  const float clear_zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, clear_position);
  for (int k = 1; k < 4; ++k)
    glClearBufferfv(GL_COLOR, k, clear_zero);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const CameraFrustum f = camera_frustum(camera, width, height, *scene_, jitter);
  const glm::mat4 view_projection = f.projection * f.view;
  glUseProgram(gbuffer_program_.id());
  scene_->bind();
  glUniformMatrix4fv(gbuffer_program_.uniform("u_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(view_projection));
  glUniform3fv(gbuffer_program_.uniform("u_camera_position"), 1, &camera.position.x);
  for (int k = 0; k < int(scene_->scene().objects.size()); ++k)
    scene_->draw_object(gbuffer_program_, k, RasterMesh::kSource);
}

TracePass GeometryFieldMethod::frame_pass(int width, int height) {
  if (settings_.pass != TracePass::kAuto)
    return settings_.pass;
  // The counting build (GF_COUNT_WORK) draws a frame between timed ones in the benchmarks: it
  // shares the trial of its program.
  std::string key = trace_defines();
  const std::string counting = "#define GF_COUNT_WORK 1\n";
  if (const size_t at = key.find(counting); at != std::string::npos)
    key.erase(at, counting.size());
  restart_pass_trial(pass_trial_, key + std::to_string(width) + "x" + std::to_string(height));
  return next_trace_pass(pass_trial_);
}

bool GeometryFieldMethod::render_tracing(const Camera& camera, Framebuffer& target,
                                         glm::vec2 jitter, TracePass pass) {
  target.bind();
  glDisable(GL_DEPTH_TEST);
  const ShaderProgram* built = trace_program(pass);
  if (built == nullptr)
    return false;
  const ShaderProgram& program = *built;
  glUseProgram(program.id());
  scene_->bind();
  if (settings_.count_work)
    work_.clear();
  glBindTextureUnit(gpu::UNIT_GBUFFER_POSITION, gbuffer_.texture(0));
  glBindTextureUnit(gpu::UNIT_GBUFFER_NORMAL, gbuffer_.texture(1));
  glBindTextureUnit(gpu::UNIT_GBUFFER_GEOMETRIC, gbuffer_.texture(2));
  glBindTextureUnit(gpu::UNIT_GBUFFER_ALBEDO, gbuffer_.texture(3));
  const auto u = [&](const char* name) { return program.uniform(name); };
  scene_->set_uniforms(program);
  set_camera_uniforms(program, camera, target.width(), target.height(), jitter);
  glUniform1i(u("u_self_reflection"), settings_.self_reflection ? 1 : 0);
  glUniform1i(u("u_intersect_bvh"), settings_.intersect == MeshIntersection::kBvh ? 1 : 0);
  glUniform1i(u("u_max_depth"), settings_.max_depth);
  glUniform1f(u("u_min_weight"), settings_.min_weight);
  glUniform1i(u("u_max_rays"), settings_.max_rays);
  if (pass == TracePass::kFragment)
    scene_->draw_fullscreen();
  else
    dispatch_tracing(program, target);
  return true;
}

void GeometryFieldMethod::render(const Camera& camera, Framebuffer& target, glm::vec2 jitter,
                                 FrameStats* stats) {
  follow_settings();
  const TracePass pass = frame_pass(target.width(), target.height());
  const bool trial = settings_.pass == TracePass::kAuto && !pass_trial_done(pass_trial_);
  PassClock clock(stats != nullptr || trial);
  render_gbuffer(camera, target.width(), target.height(), jitter);
  const double gbuffer_ms = clock.read();
  const bool drawn = render_tracing(camera, target, jitter, pass);
  const double ms = clock.read();
  if (trial)  // a pass whose program does not build loses the trial
    record_trace_pass(
        pass_trial_, pass,
        drawn ? clock.gpu_ms(1) - clock.gpu_ms(0) : std::numeric_limits<double>::infinity());
  if (stats == nullptr)
    return;
  stats->milliseconds += ms;
  stats->gpu_milliseconds += clock.gpu_ms(1);
  stats->add_part("G-buffer", gbuffer_ms);
  stats->add_part("tracing", ms - gbuffer_ms);
  stats->add_gpu_part("G-buffer", clock.gpu_ms(0));
  stats->add_gpu_part("tracing", clock.gpu_ms(1) - clock.gpu_ms(0));
  long long traced = 0, rays = 0;
  for (const glm::vec4& h : target.read_hits()) {
    if (h.x >= 0.0f && scene_->scene().objects[size_t(h.x)].material.type != MaterialType::kDiffuse)
      ++traced;
    rays += (long long)(h.y);
  }
  stats->add_count("traced pixels", double(traced));
  stats->add_count("secondary rays", double(rays));
  if (settings_.count_work)
    add_work_counts(*stats, work_.read());
}

bool GeometryFieldMethod::reload_shaders_if_changed(std::string& error) {
  std::vector<ShaderProgram*> programs = {&gbuffer_program_};
  for (auto& [defines, program] : trace_programs_)
    programs.push_back(program.get());
  return reload_programs_if_changed(programs, error);
}

std::string GeometryFieldMethod::summary(const FrameStats& per_sample) const {
  const double traced = per_sample.count("traced pixels");
  const double rays = per_sample.count("secondary rays");
  const double tracing_ms = per_sample.part_ms("tracing");
  if (rays <= 0.0)
    return "";
  char line[384];
  std::snprintf(line, sizeof(line),
                "%.2f secondary rays per traced pixel; tracing %.1f ns per traced pixel per bounce",
                traced > 0.0 ? rays / traced : 0.0, tracing_ms * 1e6 / rays);
  std::string text = line;
  const double lookups = per_sample.count(work_count_name(gpu::WORK_LOOKUPS));
  const double traversals = per_sample.count(work_count_name(gpu::WORK_BVH_TRAVERSALS));
  if (lookups > 0.0) {
    std::snprintf(line, sizeof(line),
                  "\nper field lookup: %.1f field texel fetches, %.1f image texel fetches, %.1f "
                  "Newton steps",
                  per_sample.count(work_count_name(gpu::WORK_FIELD_FETCHES)) / lookups,
                  per_sample.count(work_count_name(gpu::WORK_IMAGE_FETCHES)) / lookups,
                  per_sample.count(work_count_name(gpu::WORK_NEWTON_STEPS)) / lookups);
    text += line;
  }
  if (traversals > 0.0) {
    std::snprintf(line, sizeof(line), "\nper BVH traversal: %.1f nodes, %.1f triangles",
                  per_sample.count(work_count_name(gpu::WORK_BVH_NODES)) / traversals,
                  per_sample.count(work_count_name(gpu::WORK_BVH_TRIANGLES)) / traversals);
    text += line;
  }
  return text;
}

std::vector<std::string> GeometryFieldMethod::notes() const {
  std::vector<std::string> notes;
  const Scene& scene = scene_->scene();
  const std::vector<GpuAsset>& assets = scene_->assets().assets();
  for (size_t m = 0; m < scene.meshes.size() && m < assets.size(); ++m) {
    if (assets[m].samples_per_side == 0)
      notes.push_back(missing_asset_message(scene.meshes[m], scene.filename, "geometry field") +
                      ": traced through its BVH");
  }
  return notes;
}

std::string GeometryFieldMethod::pass_status() const {
  if (settings_.pass != TracePass::kAuto)
    return trace_pass_name(settings_.pass);
  return describe_pass_trial(pass_trial_);
}

bool GeometryFieldMethod::pass_settled() const {
  return settings_.pass != TracePass::kAuto || pass_trial_done(pass_trial_);
}

std::string GeometryFieldMethod::status() const {
  const Scene& scene = scene_->scene();
  const std::vector<GpuAsset>& assets = scene_->assets().assets();
  std::string by_field, by_bvh;
  const bool automatic = settings_.intersect == MeshIntersection::kAuto;
  const std::vector<Route> routes = automatic ? auto_routes() : std::vector<Route>();
  for (size_t m = 0; m < scene.meshes.size() && m < assets.size(); ++m) {
    const std::string name = std::filesystem::path(scene.meshes[m].file).filename().string();
    const bool field = assets[m].samples_per_side > 0;
    const std::string why = automatic ? " (auto: " + routes[m].why + ")" : "";
    if (field && settings_.intersect != MeshIntersection::kBvh && !scene_->bvh_route(int(m)))
      by_field += (by_field.empty() ? "" : ", ") + name + why;
    else
      by_bvh += (by_bvh.empty() ? "" : ", ") + name + (field ? why : " (no field)");
  }
  const std::string pass = "tracing pass: " + pass_status();
  if (by_field.empty() && by_bvh.empty())
    return pass;
  return "meshes by field: " + (by_field.empty() ? "none" : by_field) +
         "; by BVH: " + (by_bvh.empty() ? "none" : by_bvh) + "\n" + pass;
}

}  // namespace gfield
