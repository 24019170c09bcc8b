#pragma once
// The one GPU scene every method draws from: the scene description (CPU), its objects and lights
// in the contract's std430 storage buffers, the environment texture, the mesh assets (loaded as
// methods ask for them), the proxy cube that rasterises analytic shapes, and the helpers that
// bind all of it to the contract's slots (shaders/lib/contract.glsl) and draw one object.
// Editing objects, materials or lights and calling update() refills the two buffers only.

#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gfield/check.hpp"
#include "gfield/scene.hpp"
#include "runtime/gl_object.hpp"
#include "runtime/gpu_assets.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

/// Which of its meshes a mesh object is drawn as (GpuAsset::source / ::parameterized).
enum class RasterMesh { kSource, kParameterized };

class GpuScene {
 public:
  /// Keeps `scene`, uploads its environment, objects and lights (no mesh assets yet). Needs a
  /// current GL 4.5 context. False with "FILE: problem" when the environment does not load.
  bool load(const Scene& scene, std::string& error);
  /// Loads the mesh assets `needs` asks for (those not loaded yet), then refreshes the buffers.
  bool require(const AssetNeeds& needs, std::string& error);

  /// The scene drawn; after changing objects, materials or lights call update().
  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }
  /// Object k of scene() (GF_DCHECK: one of its objects).
  const SceneObject& scene_object(int k) const {
    GF_DCHECK(k >= 0 && size_t(k) < scene_.objects.size(), "an object outside the scene");
    return scene_.objects[size_t(k)];
  }
  /// Refills the objects and lights buffers from scene() (the assets stay).
  void update();

  const GpuAssets& assets() const { return assets_; }
  /// Per mesh of scene(): 1 when the mesh is traced through its BVH by choice although it has a
  /// field (--intersect auto: GpuObject::image.w); refreshes the objects buffer.
  void set_bvh_routes(std::vector<char> by_bvh);
  /// Whether mesh `mesh` is traced through its BVH by choice (set_bvh_routes).
  bool bvh_route(int mesh) const {
    return size_t(mesh) < bvh_routes_.size() && bvh_routes_[size_t(mesh)] != 0;
  }
  /// Diagonal of the bounds of all objects and the camera (scene units, at least 1e-3).
  float extent() const { return extent_; }

  /// Binds the objects and lights buffers, the asset textures (geometry images, their albedo,
  /// fields, the meshes' own textures) and the environment to their contract slots.
  void bind() const;
  /// Sets the scene uniforms of `program` (in use): u_object_count, u_light_count, u_ambient,
  /// u_scene_extent and the environment's u_env_type, u_env_color, u_env_intensity.
  void set_uniforms(const ShaderProgram& program) const;
  /// The per-object uniforms of object `object` (set_object_uniforms sets them).
  struct ObjectUniforms {
    glm::mat4 to_world{1.0f};
    glm::mat4 to_object{1.0f};
    glm::mat3 normal_to_world{1.0f};
    int shape = 0;                 ///< ShapeType
    glm::vec4 shape_params{0.0f};  ///< radius, height, thickness, 0
    glm::vec3 shape_size{0.0f};
    glm::vec3 proxy_half{1.0f};  ///< analytic: half extents of its bounds, grown a little; mesh: 1
    int mesh = -1;               ///< Shape::mesh of a mesh object, else -1
    int gi_size = 0;             ///< a mesh's geometry-image size n
  };
  ObjectUniforms object_uniforms(int object) const;
  /// Sets the per-object uniforms of `program` (in use) for object `object`: u_to_world,
  /// u_to_object, u_normal_to_world, u_object, u_shape, u_shape_params, u_shape_size,
  /// u_proxy_half (analytic: the half extents of its bounds, grown a little; mesh: 1) and
  /// u_gi_size.
  void set_object_uniforms(const ShaderProgram& program, int object) const;
  /// Draws object `object` with `program` (in use) after set_object_uniforms: a mesh as its
  /// `raster` mesh, an analytic shape as the proxy cube grown to its bounds (the fragments
  /// intersect the exact shape).
  void draw_object(const ShaderProgram& program, int object, RasterMesh raster) const;
  /// Draws one full-screen triangle (shaders/fullscreen.vert).
  void draw_fullscreen() const;

  /// The objects and lights buffers (the contract's GpuObject[] and GpuLight[]), the environment
  /// texture and the proxy cube, for readers of the GPU scene (the web export).
  GLuint objects_buffer() const { return objects_.id(); }
  GLuint lights_buffer() const { return lights_.id(); }
  GLuint environment_texture() const { return environment_.id(); }
  const GpuMesh& proxy_cube() const { return proxy_; }

  /// Object-space bounds [lo, hi] of scene().objects[object]: its shape's bounds, or its mesh
  /// asset's box (mesh coordinates).
  void object_local_bounds(int object, glm::vec3& lo, glm::vec3& hi) const;
  /// World-space axis-aligned bounds of scene().objects[object] (scene units).
  void object_world_bounds(int object, glm::vec3& lo, glm::vec3& hi) const;

 private:
  Scene scene_;
  GpuAssets assets_;
  std::vector<char> bvh_routes_;  ///< per mesh, set_bvh_routes
  GlBuffer objects_;
  GlBuffer lights_;
  GlTexture environment_;
  GpuMesh proxy_;
  GlVertexArray empty_;
  float extent_ = 1.0f;
};

/// Grows the world box [lo, hi] by the 8 corners of the object-space box [box_lo, box_hi] mapped
/// by `to_world`.
void grow_world_bounds(const glm::mat4& to_world, glm::vec3 box_lo, glm::vec3 box_hi, glm::vec3& lo,
                       glm::vec3& hi);

/// Sets the camera uniforms of shaders/lib/camera.glsl for `program` (in use): the ray through
/// pixel p + jitter of a width x height picture, as gfield::camera_ray.
void set_camera_uniforms(const ShaderProgram& program, const Camera& camera, int width, int height,
                         glm::vec2 jitter);

/// Near and far planes (x, y) that keep every object but `skip` in a view from `eye` whose
/// directions make at most acos(edge_cosine) with its axis: far just beyond the farthest corner
/// of their world bounds; near half the depth the nearest box `eye` is outside of can have
/// (its distance times edge_cosine), at most 1e-4 far when `eye` is inside a box, at least 1e-7
/// far. A unit object beside a floor of 1e6 is not clipped, whatever the scene's extent.
glm::vec2 depth_range(glm::vec3 eye, const GpuScene& scene, float edge_cosine, int skip = -1);

/// The perspective view-projection of `camera` for a width x height target, the sample offset
/// `jitter` (pixels) applied, its planes depth_range(camera.position): the frustum every method
/// rasterises with.
struct CameraFrustum {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};  ///< jitter included
  float near_plane = 0.0f;
  float far_plane = 0.0f;
};
CameraFrustum camera_frustum(const Camera& camera, int width, int height, const GpuScene& scene,
                             glm::vec2 jitter);

/// The narrowest vertical field of view gfield-view renders, in degrees: below it float camera
/// rays and vertex positions no longer resolve the view (a checkered quad rendered exactly at
/// 3e-4 degrees and at 17-19 dB against the reference tracer at 1e-4, at 128^2 and 1024^2).
/// The reference tracer (double) takes any field of view in (0, 180).
inline constexpr float kMinViewFovDegrees = 1e-3f;
/// What keeps `camera` from being rendered (its field of view below kMinViewFovDegrees), "" if
/// nothing.
std::string camera_resolution_problem(const Camera& camera);

/// Loads the environment's images and uploads them as the RGBA32F 2D array texture of
/// shaders/lib/scene_environment.glsl (equirect: layer 0; cube: the 6 faces in layers 0-5;
/// analytic environments: one 1 x 1 layer). False with "FILE: problem" when an image fails.
bool upload_environment_texture(const EnvironmentDesc& desc, GlTexture& texture,
                                std::string& error);

}  // namespace gfield
