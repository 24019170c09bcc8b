// The scene's environment on the GPU: the same function as core's environment_radiance (studio,
// constant colour, equirectangular image or six cube faces, times the intensity), with the
// images read by texelFetch and filtered here as gfield::sample_bilinear does.

#include "lib/contract.glsl"
#include "lib/environment.glsl"

layout(binding = UNIT_ENVIRONMENT) uniform sampler2DArray u_env_images;  // equirect: layer 0; cube: 6 layers
uniform int u_env_type;
uniform vec3 u_env_color;
uniform float u_env_intensity;

// gfield::sample_bilinear at continuous pixel coordinates (x, y), pixel centres at + 0.5.
vec3 env_bilinear(int layer, float x, float y, bool wrap_x) {
  ivec2 size = textureSize(u_env_images, 0).xy;
  float fx = x - 0.5f;
  float fy = clamp(y - 0.5f, 0.0f, float(size.y - 1));
  int x0 = int(floor(fx));
  int y0 = int(floor(fy));
  float ax = fx - float(x0);
  float ay = fy - float(y0);
  int xa = x0;
  int xb = x0 + 1;
  if (wrap_x) {
    xa = ((xa % size.x) + size.x) % size.x;
    xb = ((xb % size.x) + size.x) % size.x;
  } else {
    xa = clamp(xa, 0, size.x - 1);
    xb = clamp(xb, 0, size.x - 1);
  }
  int ya = clamp(y0, 0, size.y - 1);
  int yb = min(ya + 1, size.y - 1);
  vec3 top = mix(texelFetch(u_env_images, ivec3(xa, ya, layer), 0).rgb,
                 texelFetch(u_env_images, ivec3(xb, ya, layer), 0).rgb, ax);
  vec3 bottom = mix(texelFetch(u_env_images, ivec3(xa, yb, layer), 0).rgb,
                    texelFetch(u_env_images, ivec3(xb, yb, layer), 0).rgb, ax);
  return mix(top, bottom, ay);
}

// Radiance arriving from unit direction d.
vec3 environment_radiance(vec3 d) {
  vec3 radiance = vec3(0.0f);
  if (u_env_type == ENV_STUDIO) {
    radiance = studio_environment(d);
  } else if (u_env_type == ENV_CONSTANT) {
    radiance = u_env_color;
  } else if (u_env_type == ENV_EQUIRECT) {
    vec2 uv = env_equirect_uv(d);
    vec2 size = vec2(textureSize(u_env_images, 0).xy);
    radiance = env_bilinear(0, uv.x * size.x, uv.y * size.y, true);
  } else {
    vec3 c = env_cube_coords(d);
    vec2 size = vec2(textureSize(u_env_images, 0).xy);
    radiance = env_bilinear(int(c.z), c.x * size.x, c.y * size.y, false);
  }
  return radiance * u_env_intensity;
}
