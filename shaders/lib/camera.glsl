// The camera of a full-screen pass (set by runtime/gpu_scene.cpp's set_camera_uniforms) and the
// ray of a pixel's sample: the contract's gf_camera_direction through the pixel centre moved by
// u_jitter, as gfield::camera_ray and the reference tracer's sample positions. A compute stage
// (GF_COMPUTE defined) has no fragment, only camera_direction_at.

#include "lib/contract.glsl"

uniform vec3 u_camera_position;
uniform vec3 u_camera_forward;
uniform vec3 u_camera_right;
uniform vec3 u_camera_up;
uniform vec2 u_tan_half;    // tan(fov/2) * aspect, tan(fov/2)
uniform vec2 u_image_size;  // the picture, pixels
uniform vec2 u_jitter;      // sample offset from the pixel centre, pixels (x right, y down)

// The sample's ray at `window` (pixels from the bottom left of the frame, a pixel's centre at
// +0.5, as gl_FragCoord.xy).
vec3 camera_direction_at(vec2 window) {
  vec2 pixel = vec2(window.x, u_image_size.y - window.y) + u_jitter;
  return gf_camera_direction(u_camera_forward, u_camera_right, u_camera_up, u_tan_half,
                             u_image_size, pixel);
}

#ifndef GF_COMPUTE
// This fragment's sample's ray.
vec3 camera_direction() { return camera_direction_at(gl_FragCoord.xy); }
#endif
