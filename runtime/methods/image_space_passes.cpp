#include "runtime/methods/image_space_passes.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gfield/gpu_contract.hpp"
#include "gfield/thickness.hpp"

namespace gfield {

bool ImageSpacePasses::load(GpuScene& scene, const std::filesystem::path& shader_dir,
                            std::string& error) {
  scene_ = &scene;
  AssetNeeds needs;
  needs.parameterized_meshes = true;  // refractors: geometry-image uvs reach d_n
  needs.source_meshes = true;         // opaque meshes: their own uvs and base colour
  return scene.require(needs, error) && load_thickness_maps(error) &&
         forward_program_.build(shader_dir, {"image_space_object.vert", "image_space_forward.frag"},
                                "", error) &&
         background_program_.build(shader_dir, {"fullscreen.vert", "image_space_background.frag"},
                                   "", error);
}

bool ImageSpacePasses::load_thickness_maps(std::string& error) {
  const Scene& scene = scene_->scene();
  std::vector<ThicknessMap> maps(scene.meshes.size());
  thickness_layer_.assign(scene.meshes.size(), -1);
  int side = 1;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const std::string path = thickness_path(scene.meshes[m].geometry_image);
    if (!std::filesystem::exists(path))
      continue;
    if (!load_thickness_map(path, maps[m], error))
      return false;
    const int image_size = scene_->assets().assets()[m].image_size;
    if (maps[m].size != image_size) {
      error = path + ": " + std::to_string(maps[m].size) + "^2 does not match the " +
              std::to_string(image_size) + "^2 geometry image";
      return false;
    }
    thickness_layer_[m] = int(m);
    side = std::max(side, maps[m].size);
  }
  thickness_.make(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(thickness_.id(), 1, GL_R32F, side, side,
                     GLsizei(std::max<size_t>(1, maps.size())));
  for (size_t m = 0; m < maps.size(); ++m)
    if (thickness_layer_[m] >= 0)
      glTextureSubImage3D(thickness_.id(), 0, 0, 0, GLint(m), maps[m].size, maps[m].size, 1, GL_RED,
                          GL_FLOAT, maps[m].distance.data());
  return true;
}

bool ImageSpacePasses::check_thickness_maps(std::string& error) const {
  const Scene& scene = scene_->scene();
  for (const SceneObject& o : scene.objects) {
    if (o.shape.type != ShapeType::kMesh || o.material.type != MaterialType::kDielectric ||
        thickness_layer_[size_t(o.shape.mesh)] >= 0)
      continue;
    const std::string& image = scene.meshes[size_t(o.shape.mesh)].geometry_image;
    const std::string name = image.substr(0, image.size() - std::string(".gimage.exr").size());
    error = thickness_path(image) +
            ": missing; wyman2005 needs d_n (make it with: gfield thickness " + name + ")";
    return false;
  }
  return true;
}

glm::vec2 ImageSpacePasses::eye_depth_range(const ImageSpaceView& view, bool dielectrics) const {
  const Scene& scene = scene_->scene();
  glm::vec2 range(gpu::GF_FAR, -gpu::GF_FAR);
  for (int k = 0; k < int(scene.objects.size()); ++k) {
    if ((scene.objects[size_t(k)].material.type == MaterialType::kDielectric) != dielectrics)
      continue;
    glm::vec3 lo, hi;
    scene_->object_world_bounds(k, lo, hi);
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
      const float z = glm::dot(corner - view.position, view.forward);
      range = glm::vec2(std::min(range.x, z), std::max(range.y, z));
    }
  }
  if (range.x > range.y)
    return view.near_far;
  // A margin of 1% of the scene against rounding at the bounds.
  const float margin = 0.01f * scene_->extent();
  return glm::vec2(std::max(view.near_far.x, range.x - margin),
                   std::min(view.near_far.y, range.y + margin));
}

ImageSpaceView ImageSpacePasses::camera_view(const Camera& camera, int width, int height,
                                             glm::vec2 jitter) const {
  ImageSpaceView view;
  view.width = width;
  view.height = height;
  const CameraFrustum f = camera_frustum(camera, width, height, *scene_, jitter);
  view.near_far = glm::vec2(f.near_plane, f.far_plane);
  view.position = camera.position;
  view.forward = glm::normalize(camera.target - camera.position);
  view.right = glm::normalize(glm::cross(view.forward, camera.up));
  view.up = glm::cross(view.right, view.forward);
  const float tan_half = std::tan(glm::radians(camera.fov_degrees) * 0.5f);
  view.tan_half = glm::vec2(tan_half * float(width) / float(height), tan_half);
  view.view_projection = f.projection * f.view;
  view.jitter = jitter;
  view.refractor_depths = eye_depth_range(view, true);
  view.nearby_depths = eye_depth_range(view, false);
  return view;
}

void ImageSpacePasses::begin(const ShaderProgram& program, const ImageSpaceView& view) const {
  // Every image-space program starts here: each has the uniforms it needs of these.
  const auto u = [&](const char* name) { return program.uniform_if_declared(name); };
  glUseProgram(program.id());
  scene_->bind();
  glBindTextureUnit(gpu::UNIT_THICKNESS, thickness_.id());
  scene_->set_uniforms(program);
  glUniform3fv(u("u_camera_position"), 1, &view.position.x);
  glUniform3fv(u("u_camera_forward"), 1, &view.forward.x);
  glUniform3fv(u("u_camera_right"), 1, &view.right.x);
  glUniform3fv(u("u_camera_up"), 1, &view.up.x);
  glUniform2fv(u("u_tan_half"), 1, &view.tan_half.x);
  glUniform2f(u("u_image_size"), float(view.width), float(view.height));
  glUniform2fv(u("u_near_far"), 1, &view.near_far.x);
  glUniform2fv(u("u_jitter"), 1, &view.jitter.x);
  glUniform2fv(u("u_refractor_depths"), 1, &view.refractor_depths.x);
  glUniform2fv(u("u_nearby_depths"), 1, &view.nearby_depths.x);
  glUniformMatrix4fv(u("u_view_projection"), 1, GL_FALSE, glm::value_ptr(view.view_projection));
  glUniform3fv(u("u_eye"), 1, &view.position.x);
  glUniform3fv(u("u_forward"), 1, &view.forward.x);
  glUniform1i(u("u_facing"), 0);
}

void ImageSpacePasses::draw_object(const ShaderProgram& program, int object) const {
  const SceneObject& o = scene_->scene().objects[size_t(object)];
  const bool refractor = o.material.type == MaterialType::kDielectric;
  glUniform1f(program.uniform_if_declared("u_alpha"), o.material.ior);
  glUniform1i(
      program.uniform_if_declared("u_thickness_layer"),
      o.shape.type == ShapeType::kMesh && refractor ? thickness_layer_[size_t(o.shape.mesh)] : -1);
  scene_->draw_object(program, object,
                      refractor ? RasterMesh::kParameterized : RasterMesh::kSource);
}

}  // namespace gfield
