#include "runtime/field_probe.hpp"

#include <algorithm>

#include "gfield/gpu_contract.hpp"
#include "gfield/stopwatch.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

namespace {

// Rays in a kProbeWidth x height grid, row-major from texel row 0.
constexpr int kProbeWidth = 256;

/// The probe's textures: the rays' origins + t_min, directions + t_max and self origins +
/// facing (RGBA32F), and the two outputs, hits and normals.
struct ProbeTextures {
  int width = kProbeWidth;
  int height = 1;
  GlTexture origins, directions, self, hits, normals;
};

void upload_rays(const std::vector<Ray>& rays, const std::vector<glm::vec4>& self,
                 ProbeTextures& t) {
  t.height = std::max(1, int((rays.size() + kProbeWidth - 1) / kProbeWidth));
  const size_t texels = size_t(t.width) * size_t(t.height);
  std::vector<glm::vec4> origins(texels, glm::vec4(0.0f));
  std::vector<glm::vec4> directions(texels, glm::vec4(0.0f, 0.0f, 1.0f, -1.0f));
  for (size_t i = 0; i < rays.size(); ++i) {
    origins[i] = glm::vec4(rays[i].origin, rays[i].t_min);
    directions[i] = glm::vec4(rays[i].direction, rays[i].t_max);
  }
  std::vector<glm::vec4> self_texels(self);
  self_texels.resize(texels, glm::vec4(0.0f));
  for (GlTexture* texture : {&t.origins, &t.directions, &t.self, &t.hits, &t.normals}) {
    texture->make(GL_TEXTURE_2D);
    glTextureStorage2D(texture->id(), 1, GL_RGBA32F, t.width, t.height);
  }
  glTextureSubImage2D(t.origins.id(), 0, 0, 0, t.width, t.height, GL_RGBA, GL_FLOAT,
                      origins.data());
  glTextureSubImage2D(t.directions.id(), 0, 0, 0, t.width, t.height, GL_RGBA, GL_FLOAT,
                      directions.data());
  glTextureSubImage2D(t.self.id(), 0, 0, 0, t.width, t.height, GL_RGBA, GL_FLOAT,
                      self_texels.data());
}

/// The probe program's defines for `query`.
std::string probe_defines(const ProbeQuery& query) {
  std::string defines = "#define PROBE_WIDTH " + std::to_string(kProbeWidth) + "\n";
  if (query.bvh)
    return defines + "#define PROBE_BVH 1\n";
  return defines + (query.self.empty() ? "" : "#define PROBE_LEAVING 1\n");
}

/// Draws the probe pass 1 + `timed` times; the median ms of the timed passes (0: none), each
/// from a finished GPU to the pass's end (glFinish: llvmpipe's timestamp queries do not wait for
/// its rasteriser threads).
double draw_passes(int timed) {
  std::vector<double> ms;
  for (int pass = 0; pass <= timed; ++pass) {
    glFinish();
    const Stopwatch watch;
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    if (pass > 0)
      ms.push_back(watch.milliseconds());
  }
  if (ms.empty())
    return 0.0;
  std::nth_element(ms.begin(), ms.begin() + long(ms.size() / 2), ms.end());
  return ms[ms.size() / 2];
}

/// Binds what the probe program reads and sets its uniforms for `query` on asset `a`.
void bind_query(const GpuAssets& assets, const GpuAsset& a, const ProbeQuery& query,
                const ShaderProgram& program) {
  if (query.bvh) {
    assets.bvhs().bind();
    glUniform1i(program.uniform("u_bvh_root"), a.bvh_root);
    return;
  }
  glBindTextureUnit(gpu::UNIT_GI_POSITIONS, assets.positions());
  glBindTextureUnit(gpu::UNIT_GI_NORMALS, assets.normals());
  glBindTextureUnit(gpu::UNIT_FIELDS, assets.fields());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BUFFER_FIELD_LINES, assets.field_lines());
  glUniform3i(program.uniform("u_asset"), a.layer, a.samples_per_side, a.image_size);
  glUniform2i(program.uniform("u_image_origin"), a.image_origin.x, a.image_origin.y);
  glUniform4i(program.uniform("u_field"), a.field_layer, a.field_lines, a.field_interior,
              assets.field_bits() + 256 * a.field_layers);
  glUniform3fv(program.uniform("u_box_min"), 1, &a.box.min.x);
  glUniform3fv(program.uniform("u_box_max"), 1, &a.box.max.x);
  glUniform1i(program.uniform("u_mode"), int(query.mode));
  if (query.self.empty()) {
    glUniform1i(program.uniform("u_last"), query.last_hit ? 1 : 0);
    return;
  }
  glUniform1f(program.uniform("u_self_t_min"), query.self_t_min);
}

}  // namespace

bool probe_rays_gpu(const GpuAssets& assets, int asset, const std::vector<Ray>& rays,
                    const ProbeQuery& query, int timed, const std::string& shader_dir,
                    ProbeResult& result, std::string& error) {
  if (asset < 0 || asset >= int(assets.assets().size())) {
    error = "probe: no asset " + std::to_string(asset);
    return false;
  }
  const GpuAsset& a = assets.asset(asset);
  if (query.bvh && a.bvh_root < 0) {
    error = "probe: asset " + std::to_string(asset) + " has no BVH loaded";
    return false;
  }
  if (!query.self.empty() && (query.self.size() != rays.size() || query.last_hit)) {
    error = "probe: rays leaving the surface need a self origin each and look up first hits";
    return false;
  }
  ShaderProgram program;
  if (!program.build(shader_dir, {"fullscreen.vert", "field_probe.frag"}, probe_defines(query),
                     error))
    return false;
  ProbeTextures t;
  upload_rays(rays, query.self, t);
  GlFramebuffer framebuffer;
  GlVertexArray vertex_array;
  glNamedFramebufferTexture(framebuffer.make(), GL_COLOR_ATTACHMENT0, t.hits.id(), 0);
  glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT1, t.normals.id(), 0);
  const GLenum outputs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(framebuffer.id(), 2, outputs);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, t.width, t.height);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program.id());
  glBindTextureUnit(gpu::UNIT_PROBE_ORIGINS, t.origins.id());
  glBindTextureUnit(gpu::UNIT_PROBE_DIRECTIONS, t.directions.id());
  glBindTextureUnit(gpu::UNIT_PROBE_SELF, t.self.id());
  bind_query(assets, a, query, program);
  glUniform1i(program.uniform("u_ray_count"), int(rays.size()));
  glBindVertexArray(vertex_array.make());
  result.ms = draw_passes(timed);
  std::vector<glm::vec4> hits(size_t(t.width) * size_t(t.height)), normals(hits.size());
  const GLsizei bytes = GLsizei(hits.size() * sizeof(glm::vec4));
  glGetTextureImage(t.hits.id(), 0, GL_RGBA, GL_FLOAT, bytes, hits.data());
  glGetTextureImage(t.normals.id(), 0, GL_RGBA, GL_FLOAT, bytes, normals.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (const GLenum gl_error = glGetError(); gl_error != GL_NO_ERROR) {
    error = "probe: OpenGL error " + std::to_string(gl_error);
    return false;
  }
  hits.resize(rays.size());
  result.hits = std::move(hits);
  result.normals.resize(rays.size());
  for (size_t i = 0; i < rays.size(); ++i)
    result.normals[i] = glm::vec3(normals[i]);
  return true;
}

}  // namespace gfield
