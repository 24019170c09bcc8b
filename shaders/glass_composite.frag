#version 450
// The glass method's final pass (Mukai et al. 2013, Figure 8): each pixel takes its colour from
// the scene image of its refraction class, the class read from the depth-peeled glass layers.
// On top, what the paper leaves for future work: the Fresnel transmittance of the interfaces the
// pixel's light crosses and the Fresnel reflection at the glass (the reflected ray meets the
// scene's opaque analytic shapes or the environment), and the environment seen through the glass
// (its direction by an exact per-pixel trace of the glass, which has no vertices). Paths the
// displacement does not model are traced per pixel: exactly against the analytic shapes, and
// against the undisplaced scene image by a screen-space march for the meshes.
#include "lib/shapes.glsl"
#include "lib/optics.glsl"
#include "lib/scene_environment.glsl"
#include "lib/glass_shading.glsl"
#include "lib/camera.glsl"

// Peeled layers (GLASS_LAYERS of the contract, in units UNIT_PEEL_LAYERS + k): x code (-1:
// none), y depth.
layout(binding = UNIT_PEEL_LAYERS) uniform sampler2D u_layers[GLASS_LAYERS];
// rgb radiance, a depth (2: none)
layout(binding = UNIT_CLASS_IMAGES) uniform sampler2DArray u_class_images;

uniform int u_layer_of_class[GLASS_CLASSES];  // class -> layer of u_class_images (-1: not drawn)
uniform int u_glass_shape;        // SHAPE_SLAB or SHAPE_HOLLOW_CYLINDER
uniform vec4 u_glass_params;      // radius, height, thickness
uniform vec3 u_glass_size;
uniform mat4 u_glass_to_object;
uniform mat4 u_glass_to_world;
uniform float u_ior;
uniform vec3 u_absorption;
uniform bool u_fresnel;
uniform bool u_trace_verge;     // the cylinder's verge traced per pixel instead of displaced
uniform float u_epsilon;          // ray offset (scene units)
uniform mat4 u_view_projection;   // of the class images (jitter included)
uniform float u_near;             // their clip planes
uniform float u_far;
uniform float u_scene_extent;
uniform bool u_has_meshes;        // meshes are drawn: traced rays look for them by screen_march

#define GLASS_MARCH_STEPS 48

// View-space distance of a window depth of the class images' perspective projection.
float linear_depth(float window_z) {
  float z = 2.0f * window_z - 1.0f;
  return 2.0f * u_near * u_far / (u_far + u_near - z * (u_far - u_near));
}


layout(location = 0) out vec4 o_color;

// The refraction class of a pattern of peeled surface codes (glass.cpp's glass_class), -1 for a
// pattern the displacement does not model.
int glass_class(int codes[GLASS_LAYERS], int count) {
  if (count == 0) return 0;
  if (u_glass_shape == SHAPE_SLAB) {
    // In through one face, out through the opposite one: the plate of that pair of faces.
    if (count == 2 && codes[0] % 2 == 0 && codes[1] == codes[0] + 1) return 1 + codes[0] / 2;
    return -1;
  }
  // Hollow cylinder: 0/1 outer entered/left, 2/3 inner (glass entered from the interior / left).
  if (count == 4 && codes[0] == 0 && codes[1] == 3 && codes[2] == 2 && codes[3] == 1) return 4;
  if (count == 2 && codes[0] == 0 && codes[1] == 1) return u_trace_verge ? -1 : 5;
  if (count == 2 && codes[0] == 0 && codes[1] == 3) return 6;
  if (count == 2 && codes[0] == 2 && codes[1] == 1) return 7;
  return -1;
}

// The surface of the glass at object-space point p with outward normal n: slab face
// 2 * axis + (1 on the + side) (axis 0 X, 1 Y, 2 Z); hollow cylinder 0 outer, 1 inner, 2 rims.
int glass_surface(vec3 p, vec3 n) {
  if (u_glass_shape == SHAPE_SLAB) {
    vec3 a = abs(n);
    int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    return 2 * axis + (n[axis] > 0.0f ? 1 : 0);
  }
  if (abs(n.y) > 0.5f) return 2;
  float r = length(vec2(p.x, p.z));
  float inner = u_glass_params.x - u_glass_params.z;
  return abs(r - inner) < abs(r - u_glass_params.x) ? 1 : 0;
}

// True when the pixel's exact path (eye ray o + t d) crosses the interfaces that class `cls`
// assumes, up to its `in_front`-th refraction: otherwise the straight line's class is wrong
// there (e.g. light inside a plate totally reflected off a side face) and the pixel is traced.
bool path_matches(int cls, int in_front, vec3 o, vec3 d) {
  if (cls <= 0 || in_front == 0) return true;
  int events[6];
  int event_count = 0;
  int refractions = 0;
  bool inside = false;
  for (int k = 0; k < 6 && refractions < in_front; k++) {
    vec3 lo = (u_glass_to_object * vec4(o, 1.0f)).xyz;
    vec3 ld = (u_glass_to_object * vec4(d, 0.0f)).xyz;
    ShapeHit h = intersect_shape(u_glass_shape, u_glass_params, u_glass_size, lo, ld, u_epsilon,
                                 GF_FAR);
    if (!h.hit) return false;
    vec3 p = o + h.t * d;
    vec3 n = normalize(transpose(mat3(u_glass_to_object)) * h.normal);
    bool front = dot(d, n) < 0.0f;
    vec3 m = front ? n : -n;
    vec3 t = gf_refract(d, m, front ? 1.0f / u_ior : u_ior);
    bool total = dot(t, t) == 0.0f;
    events[event_count] = 2 * glass_surface(lo + h.t * ld, h.normal) + (total ? 1 : 0);
    event_count++;
    if (total) {
      d = gf_reflect(d, m);
    } else {
      d = normalize(t);
      inside = !inside;
      refractions++;
    }
    o = p;
  }
  if (refractions < in_front) return false;
  if (u_glass_shape == SHAPE_SLAB) {
    // In through a face of the class's pair, out through the opposite face, no reflection.
    int axis = cls == 1 ? 2 : (cls == 2 ? 0 : 1);
    if (events[0] % 2 == 1 || events[0] / 4 != axis) return false;
    return event_count == 1 || (event_count == 2 && events[1] == (events[0] ^ 2));
  }
  int expected[4];
  int expected_count;
  if (cls == 4) {
    expected = int[4](0, 2, 2, 0);
    expected_count = 4;
  } else if (cls == 5) {
    expected = int[4](0, 3, 0, 0);
    expected_count = 3;
  } else if (cls == 6) {
    expected = int[4](0, 2, 0, 0);
    expected_count = 2;
  } else {
    expected = int[4](2, 0, 0, 0);
    expected_count = 2;
  }
  if (event_count > expected_count) return false;
  for (int k = 0; k < event_count; k++) {
    if (events[k] != expected[k]) return false;
  }
  return true;
}

// The nearest opaque analytic shape along o + t d, t in (epsilon, t_max): its index (-1: none),
// and its t, normal and texture coordinates in `hit`.
int nearest_opaque(vec3 o, vec3 d, float t_max, out ShapeHit hit) {
  int hit_object = -1;
  hit.hit = false;
  hit.t = t_max;
  hit.normal = vec3(0.0f);
  hit.uv = vec2(0.0f);
  for (int k = 0; k < u_object_count; k++) {
    if (objects[k].kind.x == SHAPE_MESH || objects[k].kind.y != MATERIAL_DIFFUSE) continue;
    vec3 lo = (objects[k].to_object * vec4(o, 1.0f)).xyz;
    vec3 ld = (objects[k].to_object * vec4(d, 0.0f)).xyz;
    ShapeHit h = intersect_shape(objects[k].kind.x, objects[k].shape, objects[k].size.xyz, lo, ld,
                                 u_epsilon, hit.t);
    if (h.hit && h.t < hit.t) {
      hit = h;
      hit_object = k;
    }
  }
  return hit_object;
}

// Diffuse radiance of opaque shape k hit at t along o + t d.
vec3 shade_opaque(int k, ShapeHit hit, vec3 o, vec3 d) {
  vec3 p = o + hit.t * d;
  vec3 n = normalize(transpose(mat3(objects[k].to_object)) * hit.normal);
  vec3 albedo = texture_albedo(objects[k].kind.z, objects[k].color.rgb, objects[k].checker0,
                               objects[k].checker1, hit.uv);
  return glass_shade(albedo, p, n, n, d);
}

// The first surface of the undisplaced scene image (class 0: meshes included) along o + t d,
// t in (0, t_max), by marching its depth in screen space (points the camera does not see are
// not found): true with t and the colour there.
bool screen_march(vec3 o, vec3 d, float t_max, out float t_hit, out vec3 color) {
  t_hit = t_max;
  color = vec3(0.0f);
  int layer = u_layer_of_class[0];
  float t_end = min(t_max, 2.0f * u_scene_extent);
  float dt = t_end / float(GLASS_MARCH_STEPS);
  float previous_t = 0.0f;
  for (int k = 1; k <= GLASS_MARCH_STEPS; k++) {
    float t = dt * float(k);
    vec4 clip = u_view_projection * vec4(o + t * d, 1.0f);
    if (clip.w <= 0.0f) return false;
    vec3 ndc = clip.xyz / clip.w;
    if (any(greaterThan(abs(ndc.xy), vec2(1.0f)))) return false;
    ivec2 texel = ivec2((0.5f * ndc.xy + 0.5f) * u_image_size);
    vec4 stored = texelFetch(u_class_images, ivec3(texel, layer), 0);
    if (stored.a <= 1.0f) {
      float behind = linear_depth(0.5f * ndc.z + 0.5f) - linear_depth(stored.a);
      if (behind >= 0.0f && behind < 2.0f * dt + 0.01f * u_scene_extent) {
        // Bisection between the last point in front and this one.
        float lo = previous_t;
        float hi = t;
        for (int b = 0; b < 6; b++) {
          float mid = 0.5f * (lo + hi);
          vec4 c = u_view_projection * vec4(o + mid * d, 1.0f);
          vec3 n = c.xyz / c.w;
          vec4 s = texelFetch(u_class_images,
                              ivec3(ivec2((0.5f * n.xy + 0.5f) * u_image_size), layer), 0);
          if (s.a <= 1.0f && linear_depth(0.5f * n.z + 0.5f) >= linear_depth(s.a)) {
            hi = mid;
          } else {
            lo = mid;
          }
        }
        vec4 c = u_view_projection * vec4(o + hi * d, 1.0f);
        vec3 n = c.xyz / c.w;
        color = texelFetch(u_class_images,
                           ivec3(ivec2((0.5f * n.xy + 0.5f) * u_image_size), layer), 0).rgb;
        t_hit = hi;
        return true;
      }
    }
    previous_t = t;
  }
  return false;
}

// What a traced ray meets before t_max: the nearest opaque analytic shape (exact) or, outside
// the glass and when the scene has meshes, a point of the scene image found by screen_march
// (without meshes the march could only find the analytic shapes again, less exactly). True with
// its radiance.
bool scene_hit(vec3 o, vec3 d, float t_max, bool inside, out float t_hit, out vec3 radiance) {
  ShapeHit opaque_hit;
  int k = nearest_opaque(o, d, t_max, opaque_hit);
  t_hit = k >= 0 ? opaque_hit.t : t_max;
  radiance = k >= 0 ? shade_opaque(k, opaque_hit, o, d) : vec3(0.0f);
  float t_screen;
  vec3 screen_color;
  if (u_has_meshes && !inside && screen_march(o, d, t_hit, t_screen, screen_color)) {
    t_hit = t_screen;
    radiance = screen_color;
    return true;
  }
  return k >= 0;
}

// Radiance arriving along a ray that starts at a glass surface (`inside`: in the glass) after
// `depth` events of the eye path: as the reference tracer, every refraction splits the ray into
// its Fresnel-weighted reflected and transmitted parts (total internal reflection keeps it
// whole), each followed through the glass until it leaves and meets the opaque analytic shapes
// (or the meshes in the scene image) or the environment; black beyond GLASS_MAX_EVENTS events,
// branches of weight below GLASS_MIN_WEIGHT (relative to `weight`, the eye path's) are dropped.
// Near grazing incidence the inner surfaces of a hollow cylinder reflect most of the light, so
// the reflections of reflections carry much of a pixel's radiance there.
#define GLASS_MAX_EVENTS 10
#define GLASS_MIN_WEIGHT 1.0e-4f
#define GLASS_STACK 24
vec3 glass_exit_radiance(vec3 origin, vec3 direction, bool inside_glass, int depth, float weight) {
  vec3 stack_o[GLASS_STACK];
  vec3 stack_d[GLASS_STACK];
  vec3 stack_tint[GLASS_STACK];  // Fresnel weights and absorption so far (rgb)
  float stack_w[GLASS_STACK];    // Fresnel weight so far, for pruning as the reference tracer
  int stack_depth[GLASS_STACK];
  bool stack_inside[GLASS_STACK];
  int top = 0;
  stack_o[0] = origin;
  stack_d[0] = direction;
  stack_tint[0] = vec3(1.0f);
  stack_w[0] = weight;
  stack_depth[0] = depth;
  stack_inside[0] = inside_glass;
  top = 1;
  vec3 sum = vec3(0.0f);
  while (top > 0) {
    top--;
    vec3 o = stack_o[top];
    vec3 d = stack_d[top];
    vec3 tint = stack_tint[top];
    float w = stack_w[top];
    int event = stack_depth[top];
    bool inside = stack_inside[top];
    vec3 lo = (u_glass_to_object * vec4(o, 1.0f)).xyz;
    vec3 ld = (u_glass_to_object * vec4(d, 0.0f)).xyz;
    ShapeHit h = intersect_shape(u_glass_shape, u_glass_params, u_glass_size, lo, ld, u_epsilon,
                                 GF_FAR);
    float t_hit;
    vec3 hit_radiance;
    if (scene_hit(o, d, h.hit ? h.t : GF_FAR, inside, t_hit, hit_radiance)) {
      if (inside) tint *= exp(-u_absorption * t_hit);
      sum += tint * hit_radiance;
      continue;
    }
    if (!h.hit) {
      if (!inside) sum += tint * environment_radiance(d);
      continue;
    }
    if (event >= GLASS_MAX_EVENTS) continue;
    vec3 p = o + h.t * d;
    if (inside) tint *= exp(-u_absorption * h.t);
    vec3 n = normalize(transpose(mat3(u_glass_to_object)) * h.normal);
    bool front = dot(d, n) < 0.0f;
    vec3 m = front ? n : -n;
    float n1 = front ? 1.0f : u_ior;
    float n2 = front ? u_ior : 1.0f;
    vec3 t = gf_refract(d, m, n1 / n2);
    float r = dot(t, t) == 0.0f ? 1.0f : fresnel_dielectric(-dot(d, m), n1, n2);
    if (r < 1.0f && w * (1.0f - r) >= GLASS_MIN_WEIGHT && top < GLASS_STACK) {
      stack_o[top] = p;
      stack_d[top] = normalize(t);
      stack_tint[top] = tint * (1.0f - r);
      stack_w[top] = w * (1.0f - r);
      stack_depth[top] = event + 1;
      stack_inside[top] = !inside;
      top++;
    }
    if (w * r >= GLASS_MIN_WEIGHT && top < GLASS_STACK) {
      stack_o[top] = p;
      stack_d[top] = gf_reflect(d, m);
      stack_tint[top] = tint * r;
      stack_w[top] = w * r;
      stack_depth[top] = event + 1;
      stack_inside[top] = inside;
      top++;
    }
  }
  return sum;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 layers[GLASS_LAYERS];
  int codes[GLASS_LAYERS];
  int count = 0;
  for (int k = 0; k < GLASS_LAYERS; k++) {
    layers[k] = texelFetch(u_layers[k], pixel, 0);
    codes[k] = int(layers[k].x + 0.5f);
    if (layers[k].x >= 0.0f && count == k) count++;
  }
  int cls = glass_class(codes, count);
  int layer = u_layer_of_class[max(cls, 0)];
  if (layer < 0) layer = u_layer_of_class[0];
  vec4 seen = texelFetch(u_class_images, ivec3(pixel, layer), 0);
  // Glass surfaces in front of what the class image shows.
  int in_front = 0;
  for (int k = 0; k < count; k++) {
    if (seen.a > 1.0f || layers[k].y < seen.a) in_front++;
  }
  // A pattern the displacement does not model (a slab's side faces, the cylinder's rims), or a
  // pixel whose light does not take its class's path, is traced through the glass per pixel
  // (scene_hit: the analytic shapes, the meshes in the scene image, then the environment).
  bool traced = cls < 0 || !path_matches(cls, in_front, u_camera_position, camera_direction());
  bool object = !traced && seen.a <= 1.0f;
  if (traced) in_front = count;

  // The pixel's exact path through the glass for the Fresnel factors, absorption and the
  // direction the light leaves in; at every refraction the reflected light is added.
  vec3 o = u_camera_position;
  vec3 d = camera_direction();
  vec3 transmittance = vec3(1.0f);
  float weight = 1.0f;  // Fresnel weight of the eye path (the reference tracer's pruning weight)
  vec3 reflections = vec3(0.0f);
  int refractions = 0;
  bool inside = false;
  vec3 ended = vec3(-1.0f);  // a traced path's radiance when it ended on an opaque shape
  int event = 0;
  for (; event < GLASS_MAX_EVENTS && (refractions < in_front || inside || traced); event++) {
    vec3 lo = (u_glass_to_object * vec4(o, 1.0f)).xyz;
    vec3 ld = (u_glass_to_object * vec4(d, 0.0f)).xyz;
    ShapeHit h = intersect_shape(u_glass_shape, u_glass_params, u_glass_size, lo, ld, u_epsilon,
                                 GF_FAR);
    if (traced) {
      // An opaque shape before the next glass surface ends the traced path.
      float t_hit;
      vec3 hit_radiance;
      if (scene_hit(o, d, h.hit ? h.t : GF_FAR, inside, t_hit, hit_radiance)) {
        if (inside) transmittance *= exp(-u_absorption * t_hit);
        ended = transmittance * hit_radiance;
        inside = false;
        break;
      }
    }
    if (!h.hit) break;
    vec3 p = o + h.t * d;
    if (inside) transmittance *= exp(-u_absorption * h.t);
    vec3 n = normalize(transpose(mat3(u_glass_to_object)) * h.normal);
    bool front = dot(d, n) < 0.0f;
    vec3 m = front ? n : -n;
    float n1 = front ? 1.0f : u_ior;
    float n2 = front ? u_ior : 1.0f;
    vec3 t = gf_refract(d, m, n1 / n2);
    if (dot(t, t) == 0.0f) {
      d = gf_reflect(d, m);  // total internal reflection
    } else {
      if (u_fresnel) {
        float r = fresnel_dielectric(-dot(d, m), n1, n2);
        reflections += transmittance * r *
                       glass_exit_radiance(p, gf_reflect(d, m), inside, event + 1, weight * r);
        weight *= 1.0f - r;
        transmittance *= 1.0f - r;
      }
      d = normalize(t);
      inside = !inside;
      refractions++;
    }
    o = p;
  }

  vec3 radiance;
  if (object) {
    radiance = seen.rgb * transmittance;
  } else if (ended.r >= 0.0f) {
    radiance = ended;
  } else if (inside || event == GLASS_MAX_EVENTS) {
    radiance = vec3(0.0f);  // still in the glass at the depth limit
  } else {
    // Nothing drawn (or a traced path that met no opaque shape): the environment in the
    // direction the light leaves the glass.
    radiance = transmittance * environment_radiance(d);
  }
  radiance += reflections;
  o_color = vec4(radiance, 1.0f);
}
