#pragma once
// The scene as shaders/lib/scene.glsl sees it: objects and lights in std430 storage buffers
// (bindings 0 and 1), the bounds of objects, and the proxy cube that rasterises analytic shapes.
// Shared by the geometry-field renderer and the image-space renderer.

#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gfield/scene.hpp"
#include "runtime/gpu_assets.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

/// Object-space half extents of an analytic shape's bounds (as geometry/analytic_primitives'
/// shape_bounds); zero for meshes.
glm::vec3 shape_half_extent(const Shape& shape);

/// Object-space bounds [lo, hi] of scene.objects[object]: its shape's bounds, or its mesh asset's
/// box (mesh coordinates).
void object_local_bounds(const Scene& scene, const GpuAssets& assets, int object, glm::vec3& lo,
                         glm::vec3& hi);

/// World-space axis-aligned bounds [lo, hi] of scene.objects[object] (scene units): its shape's
/// bounds, or its mesh asset's box, through its transform.
void object_world_bounds(const Scene& scene, const GpuAssets& assets, int object, glm::vec3& lo,
                         glm::vec3& hi);

/// Creates the vertex buffer and vertex array of the cube [-1, 1]^3 that rasterises analytic
/// shapes: 36 vertices, attributes 0 = position, 1 = normal, 2 = uv (zero).
void create_proxy_cube(GLuint& buffer, GLuint& vertex_array);

/// Sets the camera-ray uniforms of a program (u_camera_position/forward/right/up, u_tan_half,
/// u_image_size, u_jitter): the ray through pixel p + jitter of a width x height picture, as
/// gfield::camera_ray. The program must be in use.
void set_camera_ray_uniforms(const ShaderProgram& program, const Camera& camera, int width,
                             int height, glm::vec2 jitter);

/// Sets u_env_type, u_env_color and u_env_intensity of shaders/lib/scene_environment.glsl. The
/// program must be in use.
void set_environment_uniforms(const ShaderProgram& program, const EnvironmentDesc& environment);

/// (Re)creates and fills the objects and lights buffers of shaders/lib/scene.glsl for `scene`
/// (meshes read their layer and box from `assets`). Returns the scene's extent: the diagonal of
/// the bounds of all objects and the camera (scene units, at least 1e-3).
float upload_scene_buffers(const Scene& scene, const GpuAssets& assets, GLuint& objects_buffer,
                           GLuint& lights_buffer);

/// Loads the scene's environment images and uploads them as the RGBA32F 2D array texture of
/// shaders/lib/scene_environment.glsl (equirect: layer 0; cube: the 6 faces in layers 0-5;
/// analytic environments: one 1 x 1 layer). False with "FILE: problem" when an image fails.
bool upload_environment_texture(const EnvironmentDesc& desc, GLuint& texture, std::string& error);

}  // namespace gfield
