#pragma once
// What the image-space methods (cube maps: runtime/methods/cube_map.*, screen maps:
// runtime/methods/image_space_refraction.*) share: the view of a pass as their shaders see it
// (shaders/lib/image_space.glsl), their object drawing (refractors as their parameterised meshes,
// so that d_n and the geometry-image uv reach each corner; opaque meshes as their mesh files,
// with their own uvs and base colour), the environment behind everything and the forward
// pass of the opaque objects (diffuse shading, mirrors reflecting the environment), and the
// d_n maps of wyman2005.

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/scene.hpp"
#include "runtime/gl_object.hpp"
#include "runtime/gpu_scene.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

/// The camera of one pass as the image-space shaders see it.
struct ImageSpaceView {
  glm::vec3 position{0.0f}, forward{0.0f, 0.0f, -1.0f}, right{1.0f, 0.0f, 0.0f},
      up{0.0f, 1.0f, 0.0f};
  glm::vec2 tan_half{1.0f};
  glm::vec2 near_far{0.1f, 10.0f};
  glm::vec2 refractor_depths{0.1f, 10.0f};  ///< eye-depth range of the dielectrics' bounds
  glm::vec2 nearby_depths{0.1f, 10.0f};     ///< of the other objects' bounds
  glm::mat4 view_projection{1.0f};
  glm::vec2 jitter{0.0f};  ///< sample offset from the pixel centres (x right, y down)
  int width = 0, height = 0;
};

class ImageSpacePasses {
 public:
  /// Loads the geometry images, parameterised meshes and mesh files of `scene`'s meshes and the
  /// d_n maps beside them (NAME.thickness.exr, where present), builds the shared programs.
  bool load(GpuScene& scene, const std::filesystem::path& shader_dir, std::string& error);

  /// The view of `camera` for a width x height picture at sample offset `jitter`, its search
  /// depth ranges from the objects' bounds.
  ImageSpaceView camera_view(const Camera& camera, int width, int height, glm::vec2 jitter) const;
  /// Uses `program` and sets the scene's and the view's uniforms; binds the scene and the d_n
  /// maps.
  void begin(const ShaderProgram& program, const ImageSpaceView& view) const;
  /// Draws object k with the program begun (its d_n map layer and Hurley's index set first): a
  /// dielectric mesh as its parameterised mesh, another mesh as its mesh file.
  void draw_object(const ShaderProgram& program, int object) const;
  /// The environment along every pixel's camera ray, then the objects for which `opaque(k)` is
  /// true, shaded, with depth (alpha: coverage).
  template <class Opaque>
  void draw_background_and_opaque(const ImageSpaceView& view, Opaque opaque) const;
  /// The forward shading program (opaque surfaces).
  const ShaderProgram& forward() const { return forward_program_; }
  /// Eye-depth range [near, far] of the bounds of the dielectric objects (or of all others),
  /// within the view's near and far planes.
  glm::vec2 eye_depth_range(const ImageSpaceView& view, bool dielectrics) const;
  /// False with "FILE: missing ..." when a dielectric mesh has no d_n map (wyman2005 needs one).
  bool check_thickness_maps(std::string& error) const;
  GpuScene& scene() const { return *scene_; }
  std::vector<ShaderProgram*> programs() { return {&forward_program_, &background_program_}; }

 private:
  bool load_thickness_maps(std::string& error);

  GpuScene* scene_ = nullptr;
  GlTexture thickness_;
  std::vector<int> thickness_layer_;  ///< Scene::meshes index -> layer, -1 when missing
  ShaderProgram forward_program_;
  ShaderProgram background_program_;
};

template <class Opaque>
void ImageSpacePasses::draw_background_and_opaque(const ImageSpaceView& view, Opaque opaque) const {
  glClear(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  begin(background_program_, view);
  scene_->draw_fullscreen();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  begin(forward_program_, view);
  glUniform1i(forward_program_.uniform("u_alpha_is_coverage"), 1);
  for (int k = 0; k < int(scene_->scene().objects.size()); ++k)
    if (opaque(k))
      draw_object(forward_program_, k);
}

}  // namespace gfield
