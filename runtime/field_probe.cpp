#include "runtime/field_probe.hpp"

#include <algorithm>

#include "gfield/gpu_contract.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

bool probe_field_gpu(const GpuAssets& assets, int asset, const std::vector<Ray>& rays,
                     LookupMode mode, bool last_hit, const std::string& shader_dir,
                     std::vector<glm::vec4>& hits, std::string& error) {
  if (asset < 0 || asset >= int(assets.assets().size())) {
    error = "probe: no asset " + std::to_string(asset);
    return false;
  }
  const GpuAsset& a = assets.asset(asset);
  ShaderProgram program;
  if (!program.build(shader_dir, {"fullscreen.vert", "field_probe.frag"}, "", error))
    return false;
  // Rays in a width x height grid, row-major from texel row 0.
  const int width = 256;
  const int height = std::max(1, int((rays.size() + width - 1) / width));
  std::vector<glm::vec4> origins(size_t(width) * size_t(height), glm::vec4(0.0f));
  std::vector<glm::vec4> directions(origins.size(), glm::vec4(0.0f, 0.0f, 1.0f, -1.0f));
  for (size_t i = 0; i < rays.size(); ++i) {
    origins[i] = glm::vec4(rays[i].origin, rays[i].t_min);
    directions[i] = glm::vec4(rays[i].direction, rays[i].t_max);
  }
  GlTexture textures[3];
  for (GlTexture& texture : textures) {
    texture.make(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, GL_RGBA32F, width, height);
  }
  glTextureSubImage2D(textures[0].id(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, origins.data());
  glTextureSubImage2D(textures[1].id(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT,
                      directions.data());
  GlFramebuffer framebuffer;
  GlVertexArray vertex_array;
  glNamedFramebufferTexture(framebuffer.make(), GL_COLOR_ATTACHMENT0, textures[2].id(), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program.id());
  glBindTextureUnit(gpu::UNIT_GI_POSITIONS, assets.positions());
  glBindTextureUnit(gpu::UNIT_GI_NORMALS, assets.normals());
  glBindTextureUnit(gpu::UNIT_FIELDS, assets.fields());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BUFFER_FIELD_LINES, assets.field_lines());
  glBindTextureUnit(gpu::UNIT_PROBE_ORIGINS, textures[0].id());
  glBindTextureUnit(gpu::UNIT_PROBE_DIRECTIONS, textures[1].id());
  glUniform3i(program.uniform("u_asset"), a.layer, a.samples_per_side, a.image_size);
  glUniform2i(program.uniform("u_image_origin"), a.image_origin.x, a.image_origin.y);
  glUniform4i(program.uniform("u_field"), a.field_layer, a.field_lines, a.field_interior,
              assets.field_bits() + 256 * a.field_layers);
  glUniform3fv(program.uniform("u_box_min"), 1, &a.box.min.x);
  glUniform3fv(program.uniform("u_box_max"), 1, &a.box.max.x);
  glUniform1i(program.uniform("u_mode"), int(mode));
  glUniform1i(program.uniform("u_last"), last_hit ? 1 : 0);
  glBindVertexArray(vertex_array.make());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<glm::vec4> out(origins.size());
  glGetTextureImage(textures[2].id(), 0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(glm::vec4)),
                    out.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const GLenum gl_error = glGetError();
  if (gl_error != GL_NO_ERROR) {
    error = "probe: OpenGL error " + std::to_string(gl_error);
    return false;
  }
  out.resize(rays.size());
  hits = std::move(out);
  return true;
}

}  // namespace gfield
