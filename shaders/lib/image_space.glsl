// Shared pieces of the image-space methods (runtime/methods/image_space_passes.cpp): the camera's
// projection to and from screen buffers, forward shading of opaque surfaces, the ray / depth-map
// intersection by binary search of Davis & Wyman 2007 (section 3), and what a ray leaving a
// refractor sees (nearby geometry, then the environment).
//
// Screen buffers (back faces, front faces, nearby geometry) are RGBA32F textures of the camera's
// view, possibly smaller than the picture: texel (0, 0) is the bottom-left corner. Their alpha is
// the eye depth z = dot(P - eye, forward) of the surface (scene units), IS_FAR where nothing was
// drawn.
#include "lib/scene.glsl"
#include "lib/optics.glsl"
#include "lib/camera.glsl"

uniform vec2 u_near_far;    // eye depths of the near and far planes
// The search frustums' near and far planes (eye depths): the view frustum with its depth range
// tightened to the bounds of what a map holds (the refractors, the nearby geometry), so that a
// binary search of a few steps starts from an end point close to the surface it seeks.
uniform vec2 u_refractor_depths;
uniform vec2 u_nearby_depths;

float is_eye_depth(vec3 p) { return dot(p - u_camera_position, u_camera_forward); }

// Screen coordinates in [0,1]^2 (x right, y up) of world point p; z holds its eye depth.
vec3 is_project(vec3 p) {
  vec3 r = p - u_camera_position;
  float z = dot(r, u_camera_forward);
  float x = dot(r, u_camera_right) / (z * u_tan_half.x);
  float y = dot(r, u_camera_up) / (z * u_tan_half.y);
  return vec3(0.5f * x + 0.5f, 0.5f * y + 0.5f, z);
}

// The world point at screen coordinates uv (as is_project) and eye depth z.
vec3 is_unproject(vec2 uv, float z) {
  vec2 s = (2.0f * uv - 1.0f) * u_tan_half;
  return u_camera_position + z * (u_camera_forward + s.x * u_camera_right + s.y * u_camera_up);
}

// Largest t such that o + t d stays inside the view frustum with near and far planes at the eye
// depths `depths` (o inside it), Davis & Wyman's endpoint of the binary search (Figure 3a).
float is_clip_to_frustum(vec3 o, vec3 d, vec2 depths) {
  vec3 r = o - u_camera_position;
  float z0 = dot(r, u_camera_forward), z1 = dot(d, u_camera_forward);
  float x0 = dot(r, u_camera_right), x1 = dot(d, u_camera_right);
  float y0 = dot(r, u_camera_up), y1 = dot(d, u_camera_up);
  // Each plane as a(t) = A + B t >= 0.
  vec4 A[2] = vec4[](vec4(z0 * u_tan_half.x - x0, z0 * u_tan_half.x + x0,
                          z0 * u_tan_half.y - y0, z0 * u_tan_half.y + y0),
                     vec4(z0 - depths.x, depths.y - z0, 0.0f, 0.0f));
  vec4 B[2] = vec4[](vec4(z1 * u_tan_half.x - x1, z1 * u_tan_half.x + x1,
                          z1 * u_tan_half.y - y1, z1 * u_tan_half.y + y1),
                     vec4(z1, -z1, 0.0f, 0.0f));
  float t = 1.0e30f;
  for (int g = 0; g < 2; g++) {
    for (int c = 0; c < 4; c++) {
      if (B[g][c] < 0.0f) t = min(t, max(A[g][c], 0.0f) / -B[g][c]);
    }
  }
  return t;
}

struct MapHit {
  bool found;     // the last midpoint's texel holds a surface
  vec3 position;  // that surface point (world)
  ivec2 texel;
  float alignment;  // cosine between (position - origin) and the ray
};

// Davis & Wyman 2007, section 3: binary search for o + t d against the depth map `map` (eye
// depth in alpha), `iterations` steps between o (offset against acne) and the nearer of the exit
// of the frustum whose depth range is `depths` and t_max.
// Five cases: the map's far value moves the end point; otherwise the point moves towards the
// surface from the side the ray comes from (rays going away from or towards the viewer).
MapHit is_search_depth_map(sampler2D map, vec3 o, vec3 d, int iterations, float offset,
                           vec2 depths, float t_max) {
  ivec2 size = textureSize(map, 0);
  vec3 a = o + offset * d;
  vec3 b = o + min(is_clip_to_frustum(o, d, depths), t_max) * d;
  bool away = dot(d, u_camera_forward) > 0.0f;
  MapHit h;
  h.found = false;
  h.position = vec3(0.0f);
  h.texel = ivec2(0);
  h.alignment = -1.0f;
  float z_lookup = IS_FAR;
  vec2 uv = vec2(0.0f);
  for (int i = 0; i < iterations; i++) {
    vec3 m = 0.5f * (a + b);
    vec3 p = is_project(m);
    uv = p.xy;
    h.texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
    z_lookup = texelFetch(map, h.texel, 0).a;
    if (z_lookup >= IS_FAR) {
      b = m;
    } else if (away) {
      if (p.z < z_lookup) a = m; else b = m;
    } else {
      if (p.z > z_lookup) a = m; else b = m;
    }
  }
  if (z_lookup >= IS_FAR || iterations == 0) return h;
  h.found = true;
  h.position = is_unproject((vec2(h.texel) + 0.5f) / vec2(size), z_lookup);
  vec3 to = h.position - o;
  float len = length(to);
  h.alignment = len > offset ? dot(to / len, d) : -1.0f;
  return h;
}

// ---- Forward shading of opaque surfaces (no geometry fields: mirrors see the environment) ----

// First hit of o + t d (t in (t_min, t_max)) on the analytic shape of object k (world units).
ShapeHit is_intersect_analytic(int k, vec3 o, vec3 d, float t_min, float t_max) {
  vec3 lo = (objects[k].to_object * vec4(o, 1.0f)).xyz;
  vec3 ld = (objects[k].to_object * vec4(d, 0.0f)).xyz;
  ShapeHit s = intersect_shape(objects[k].kind.x, objects[k].shape, objects[k].size.xyz, lo, ld,
                               t_min, t_max);
  if (s.hit) s.normal = normalize(transpose(mat3(objects[k].to_object)) * s.normal);
  return s;
}

// Diffuse shading as the reference tracer (albedo * (ambient + lights * cos / d^2), two sided),
// with shadow rays blocked by opaque ANALYTIC shapes only (meshes cast no shadows here).
vec3 is_shade_diffuse(int k, vec3 p, vec3 n, vec3 incoming, vec3 albedo) {
  if (dot(incoming, n) > 0.0f) n = -n;
  vec3 light_sum = u_ambient;
  for (int i = 0; i < u_light_count; i++) {
    vec3 l;
    float distance_to_light = GF_FAR;
    bool point = lights[i].direction.w > 0.5f;
    if (!point) {
      l = -lights[i].direction.xyz;
    } else {
      l = lights[i].position.xyz - p;
      distance_to_light = length(l);
      if (distance_to_light <= 0.0f) continue;
      l /= distance_to_light;
    }
    float cosine = dot(n, l);
    if (cosine <= 0.0f) continue;
    bool blocked = false;
    for (int j = 0; j < u_object_count && !blocked; j++) {
      if (objects[j].kind.x == SHAPE_MESH || objects[j].kind.y == MATERIAL_DIELECTRIC) continue;
      blocked = is_intersect_analytic(j, p + 1.0e-4f * u_scene_extent * n, l, 0.0f,
                                      distance_to_light).hit;
    }
    if (blocked) continue;
    light_sum += lights[i].color.rgb * cosine * (point ? 1.0f / (distance_to_light *
                                                                 distance_to_light) : 1.0f);
  }
  return albedo * light_sum;
}

// What an opaque surface of object k sends along -incoming: diffuse shading, a mirror's tinted
// reflection of the environment, or (a dielectric no method handles here) the environment seen
// straight through blended with its Fresnel reflection.
vec3 is_shade_surface(int k, vec3 p, vec3 n, vec3 incoming, vec3 albedo) {
  int material = objects[k].kind.y;
  if (material == MATERIAL_DIFFUSE) return is_shade_diffuse(k, p, n, incoming, albedo);
  if (dot(incoming, n) > 0.0f) n = -n;
  vec3 mirrored = environment_radiance(gf_reflect(incoming, n));
  if (material == MATERIAL_MIRROR) return objects[k].color.rgb * mirrored;
  float f = fresnel_dielectric(-dot(incoming, n), 1.0f, objects[k].color.w);
  return mix(environment_radiance(incoming), mirrored, f);
}

// ---- Rays leaving a refractor ----

#define BACKGROUND_DEPTH_MAP 0
#define BACKGROUND_ANALYTIC 1

// The nearest opaque analytic shape along o + t d, shaded, or the environment (Davis & Wyman's
// analytic background quad, generalised to every analytic opaque shape of the scene).
vec3 is_exit_analytic(vec3 o, vec3 d) {
  int best = -1;
  ShapeHit hit;
  float t_max = GF_FAR;
  for (int k = 0; k < u_object_count; k++) {
    if (objects[k].kind.x == SHAPE_MESH || objects[k].kind.y == MATERIAL_DIELECTRIC) continue;
    ShapeHit s = is_intersect_analytic(k, o, d, 0.0f, t_max);
    if (s.hit) {
      best = k;
      hit = s;
      t_max = s.t;
    }
  }
  if (best < 0) return environment_radiance(d);
  return is_shade_surface(best, o + hit.t * d, hit.normal, d, object_albedo(best, hit.uv));
}

// The nearby-geometry colour map searched like the refractor's depth maps (alignment above
// `min_alignment` counts as a hit), then the environment.
vec3 is_exit_depth_map(sampler2D nearby, vec3 o, vec3 d, int iterations, float offset,
                       float min_alignment) {
  MapHit h = is_search_depth_map(nearby, o, d, iterations, offset, u_nearby_depths, 1.0e30f);
  if (h.found && h.alignment >= min_alignment) return texelFetch(nearby, h.texel, 0).rgb;
  return environment_radiance(d);
}
