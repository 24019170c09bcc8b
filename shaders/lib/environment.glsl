// Environment lookups by direction, shared by the CPU reference tracer (core/src/environment.cpp)
// and the shaders, in the CPU/GPU dialect (docs/architecture.md; float).
//
// Directions are unit vectors in world space, +Y up.

#ifndef __cplusplus
#include "lib/contract.glsl"
#endif

// Equirectangular (latitude-longitude) map coordinates in [0,1]^2 of direction d: u = 0.5
// towards -Z, 0.75 towards +X, 0 and 1 towards +Z (the seam); v = 0 straight up (the top row of
// the image file), v = 1 straight down.
vec2 env_equirect_uv(vec3 d) {
  float u = 0.5f + atan(d.x, -d.z) / (2.0f * GF_PI);
  float v = acos(clamp(d.y, -1.0f, 1.0f)) / GF_PI;
  return vec2(u, v);
}

// Cube-map coordinates of direction d by the OpenGL rule (GL 4.5 spec, table 8.19): returns
// (s, t, face) with s, t in [0,1] and face 0..5 = +X, -X, +Y, -Y, +Z, -Z. t = 0 is the first
// (top) row of the face's image file, s = 0 its first column.
vec3 env_cube_coords(vec3 d) {
  vec3 a = abs(d);
  float sc;
  float tc;
  float ma;
  float face;
  if (a.x >= a.y && a.x >= a.z) {
    ma = a.x;
    face = d.x > 0.0f ? 0.0f : 1.0f;
    sc = d.x > 0.0f ? -d.z : d.z;
    tc = -d.y;
  } else if (a.y >= a.z) {
    ma = a.y;
    face = d.y > 0.0f ? 2.0f : 3.0f;
    sc = d.x;
    tc = d.y > 0.0f ? d.z : -d.z;
  } else {
    ma = a.z;
    face = d.z > 0.0f ? 4.0f : 5.0f;
    sc = d.z > 0.0f ? d.x : -d.x;
    tc = -d.y;
  }
  return vec3(0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f), face);
}

// 1 inside a rectangle of the sky given by its centre (azimuth az0, elevation el0) and half
// sizes, all in radians; 0 outside.
float env_softbox(float az, float el, float az0, float el0, float half_w, float half_h) {
  float da = abs(mod(az - az0 + GF_PI, 2.0f * GF_PI) - GF_PI);
  return (da < half_w && abs(el - el0) < half_h) ? 1.0f : 0.0f;
}

// The built-in "studio": below the horizon an infinite checkered floor one unit below the
// viewer (1 x 1 tiles, fading to grey with distance); above it a sky gradient with dark grid
// lines every 30 degrees of azimuth and 15 degrees of elevation, a colour band just above the
// horizon whose hue turns with the azimuth, and two bright softboxes (radiance 6 and 3).
// Azimuth is atan(d.x, -d.z): 0 towards -Z, +pi/2 towards +X.
vec3 studio_environment(vec3 d) {
  if (d.y < 0.0f) {
    vec2 p = vec2(d.x, d.z) / max(-d.y, 1e-6f);
    float tile = mod(floor(p.x) + floor(p.y), 2.0f);
    vec3 floor_color = mix(vec3(0.6f, 0.6f, 0.56f), vec3(0.08f, 0.08f, 0.1f), tile);
    float fade = clamp(length(p) / 40.0f, 0.0f, 1.0f);
    return mix(floor_color, vec3(0.34f, 0.34f, 0.33f), fade);
  }
  float az = atan(d.x, -d.z);
  float el = asin(clamp(d.y, 0.0f, 1.0f));
  vec3 sky = mix(vec3(0.85f, 0.82f, 0.75f), vec3(0.18f, 0.3f, 0.6f), sqrt(d.y));
  if (el < 0.12f) {
    float h = az / (2.0f * GF_PI) + 0.5f;
    vec3 hue = clamp(abs(mod(h * 6.0f + vec3(0.0f, 4.0f, 2.0f), 6.0f) - 3.0f) - 1.0f, 0.0f, 1.0f);
    sky = mix(vec3(0.2f, 0.2f, 0.2f), hue, 0.8f);
  }
  float ga = az / (GF_PI / 6.0f);
  float ge = el / (GF_PI / 12.0f);
  float line = min(abs(ga - floor(ga + 0.5f)), abs(ge - floor(ge + 0.5f)));
  if (line < 0.04f) {
    sky = sky * 0.3f;
  }
  sky = mix(sky, vec3(6.0f, 6.0f, 6.0f), env_softbox(az, el, 0.8f, 0.6f, 0.25f, 0.15f));
  sky = mix(sky, vec3(3.0f, 3.0f, 3.2f), env_softbox(az, el, -2.2f, 0.35f, 0.15f, 0.2f));
  return sky;
}
