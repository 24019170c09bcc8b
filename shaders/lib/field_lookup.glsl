// Geometry-field lookup (Li et al. 2006, section 3.2 step 1, plus the `refined` mode of issue 4).
//
// ONE source for the CPU and the GPU: this file is valid GLSL 4.50 and valid C++ with GLM, and
// is included verbatim by core/src/field_lookup.cpp (inside a struct whose members supply the
// fetches below) and by the runtime's shaders. Keep it in the common subset: float literals with
// an `f` suffix, no swizzles beyond .x/.y/.z/.w, no arrays as parameters, no `const` locals, no
// builtin names (step, length, sign, in, out, ...) as variable names, callees defined before
// their callers, GF_OUT/GF_INOUT for output parameters.
//
// The includer defines, before including this file (GLSL) or as members (C++):
//   int  gf_samples_per_side();             N of the field
//   vec2 gf_field_texel(int entry, int exit);  stored uv of the pair (texelFetch, row = entry)
//   int  gf_image_size();                    n of the geometry image (n >= 2)
//   vec3 gf_image_position_texel(int i, int j);  position texel, column i, scanline j (texelFetch)
//   vec3 gf_image_normal_texel(int i, int j);    normal texel (texelFetch)
//   vec3 gf_box_min();  vec3 gf_box_max();   the box (mesh coordinates) mapped to the unit cube
//
// Bilinear filtering is done here from 4 texelFetches (GL_LINEAR + GL_CLAMP_TO_EDGE semantics,
// texel centres at (i + 0.5) / n) rather than by the texture unit, whose 8-bit filter weights
// would make the GPU differ from the CPU. All math is float.
//
// Conventions (docs/geometry-field.md): rays are origin + t * direction in mesh (object)
// coordinates, t in [t_min, t_max]; a hit's t is along the given (unnormalised) direction.

#ifdef __cplusplus
#define GF_OUT(T) T&
#define GF_INOUT(T) T&
#else
#define GF_OUT(T) out T
#define GF_INOUT(T) inout T
#endif

#define GF_MODE_NEAREST 0
#define GF_MODE_LINEAR 1
#define GF_MODE_REFINED 2

// Newton iterations per candidate, the longest Newton step (texels of the geometry image), and
// the residual (distance between the line and the surface point, in box diagonals) accepted as
// an intersection.
#define GF_NEWTON_ITERATIONS 16
#define GF_NEWTON_MAX_STEP 8.0f
#define GF_NEWTON_TOLERANCE 1.0e-5f
// Least weight of the hitting pairs among the 16 for a chart border to count as a seam.
#define GF_SEAM_WEIGHT 0.999f

struct GfHit {
  bool hit;       // false: miss (or an invalid ray)
  float t;        // ray parameter of the hit
  vec2 uv;        // geometry-image uv of the hit
  vec3 position;  // mesh coordinates
  vec3 normal;    // unit normal from the geometry image
};

GfHit gf_miss() {
  GfHit h;
  h.hit = false;
  h.t = 0.0f;
  h.uv = vec2(-1.0f);
  h.position = vec3(0.0f);
  h.normal = vec3(0.0f);
  return h;
}

// Texel-centre coordinates of uv, clamped to the centres: the texel grid x in [0, n-1]^2.
vec2 gf_image_grid(vec2 uv, int n) {
  return clamp(uv * float(n) - 0.5f, vec2(0.0f), vec2(float(n - 1)));
}

// Lower-left texel of the bilinear patch holding grid point x.
ivec2 gf_image_cell(vec2 x, int n) { return min(ivec2(floor(x)), ivec2(n - 2)); }

// Bilinear position at uv (GL_LINEAR, GL_CLAMP_TO_EDGE).
vec3 gf_image_position(vec2 uv) {
  int n = gf_image_size();
  vec2 x = gf_image_grid(uv, n);
  ivec2 c = gf_image_cell(x, n);
  vec2 f = x - vec2(c);
  vec3 a = mix(gf_image_position_texel(c.x, c.y), gf_image_position_texel(c.x + 1, c.y), f.x);
  vec3 b = mix(gf_image_position_texel(c.x, c.y + 1), gf_image_position_texel(c.x + 1, c.y + 1),
               f.x);
  return mix(a, b, f.y);
}

// Bilinear normal at uv, renormalised.
vec3 gf_image_normal(vec2 uv) {
  int n = gf_image_size();
  vec2 x = gf_image_grid(uv, n);
  ivec2 c = gf_image_cell(x, n);
  vec2 f = x - vec2(c);
  vec3 a = mix(gf_image_normal_texel(c.x, c.y), gf_image_normal_texel(c.x + 1, c.y), f.x);
  vec3 b =
      mix(gf_image_normal_texel(c.x, c.y + 1), gf_image_normal_texel(c.x + 1, c.y + 1), f.x);
  return normalize(mix(a, b, f.y));
}

// Clips the line o + t d (unit-cube coordinates) against the unit cube. t0/t1: entry and exit
// parameters; f0/f1: entry and exit faces (2 * axis, + 1 for the max side: -X, +X, -Y, ...).
bool gf_clip_unit_cube(vec3 o, vec3 d, GF_OUT(float) t0, GF_OUT(float) t1, GF_OUT(int) f0,
                       GF_OUT(int) f1) {
  t0 = -3.0e38f;
  t1 = 3.0e38f;
  f0 = -1;
  f1 = -1;
  for (int axis = 0; axis < 3; axis++) {
    if (d[axis] == 0.0f) {
      if (o[axis] < 0.0f || o[axis] > 1.0f) {
        return false;
      }
      continue;
    }
    float ta = (0.0f - o[axis]) / d[axis];
    float tb = (1.0f - o[axis]) / d[axis];
    bool forward = d[axis] > 0.0f;
    float tn = forward ? ta : tb;
    float tf = forward ? tb : ta;
    if (tn > t0) {
      t0 = tn;
      f0 = 2 * axis + (forward ? 0 : 1);
    }
    if (tf < t1) {
      t1 = tf;
      f1 = 2 * axis + (forward ? 1 : 0);
    }
  }
  return f0 >= 0 && f1 >= 0 && t0 < t1;
}

// Face coordinates (s, t) of a unit-cube point on `face`: X faces (y, z), Y faces (x, z), Z faces
// (x, y).
vec2 gf_face_coords(int face, vec3 p) {
  int axis = face / 2;
  if (axis == 0) {
    return vec2(p.y, p.z);
  }
  if (axis == 1) {
    return vec2(p.x, p.z);
  }
  return vec2(p.x, p.y);
}

// Index of the sample nearest to face coordinates st: face * N^2 + b * N + a.
int gf_nearest_sample(int face, vec2 st, int n) {
  int a = clamp(int(floor(st.x * float(n))), 0, n - 1);
  int b = clamp(int(floor(st.y * float(n))), 0, n - 1);
  return face * n * n + b * n + a;
}

// The 2 x 2 samples around st (sample centres at (a + 0.5) / N, indices clamped to the face) and
// their bilinear weights, in the order (a0,b0), (a1,b0), (a0,b1), (a1,b1).
void gf_sample_cell(int face, vec2 st, int n, GF_OUT(ivec4) k, GF_OUT(vec4) w) {
  vec2 c = st * float(n) - 0.5f;
  vec2 fl = floor(c);
  vec2 f = c - fl;
  ivec2 i0 = clamp(ivec2(fl), ivec2(0), ivec2(n - 1));
  ivec2 i1 = clamp(ivec2(fl) + 1, ivec2(0), ivec2(n - 1));
  int base = face * n * n;
  k = ivec4(base + i0.y * n + i0.x, base + i0.y * n + i1.x, base + i1.y * n + i0.x,
            base + i1.y * n + i1.x);
  w = vec4((1.0f - f.x) * (1.0f - f.y), f.x * (1.0f - f.y), (1.0f - f.x) * f.y, f.x * f.y);
}

// A hit at geometry-image uv for the ray o + t d: position and normal from the image, t by
// projection onto the ray; a miss when t falls outside [t_min, t_max].
GfHit gf_hit_at(vec3 o, vec3 d, float t_min, float t_max, vec2 uv) {
  GfHit h = gf_miss();
  vec3 p = gf_image_position(uv);
  float t = dot(p - o, d) / dot(d, d);
  if (t < t_min || t > t_max) {
    return h;
  }
  h.hit = true;
  h.t = t;
  h.uv = uv;
  h.position = p;
  h.normal = gf_image_normal(uv);
  return h;
}

// Newton's method for the intersection of the line through o (directions e1, e2 span the plane
// orthogonal to it) with the geometry image's surface of bilinear patches between texel centres.
// Starts at uv, moves across patches (steps of at most GF_NEWTON_MAX_STEP texels) and succeeds
// when the surface point p is within `tolerance` (mesh units) of the line; uv and p are then the
// intersection. `seams`: also accept chart-border points across seams (see below).
bool gf_refine(vec3 o, vec3 e1, vec3 e2, float tolerance, bool seams, GF_INOUT(vec2) uv,
               GF_OUT(vec3) p) {
  int n = gf_image_size();
  vec2 x = gf_image_grid(uv, n);
  p = vec3(0.0f);
  for (int iteration = 0; iteration < GF_NEWTON_ITERATIONS; iteration++) {
    ivec2 c = gf_image_cell(x, n);
    vec2 f = x - vec2(c);
    vec3 p00 = gf_image_position_texel(c.x, c.y);
    vec3 p10 = gf_image_position_texel(c.x + 1, c.y);
    vec3 p01 = gf_image_position_texel(c.x, c.y + 1);
    vec3 p11 = gf_image_position_texel(c.x + 1, c.y + 1);
    vec3 a = mix(p00, p10, f.x);
    vec3 b = mix(p01, p11, f.x);
    p = mix(a, b, f.y);
    vec3 pu = mix(p10 - p00, p11 - p01, f.y);
    vec3 pv = b - a;
    vec2 r = vec2(dot(p - o, e1), dot(p - o, e2));
    if (dot(r, r) <= tolerance * tolerance) {
      uv = (x + 0.5f) / float(n);
      return true;
    }
    float j11 = dot(pu, e1);
    float j12 = dot(pv, e1);
    float j21 = dot(pu, e2);
    float j22 = dot(pv, e2);
    float det = j11 * j22 - j12 * j21;
    if (det == 0.0f) {
      // A collapsed patch: padding texels are copies of the nearest chart-border texel, so the
      // walk has left the chart. Where the line crosses a seam between two charts (`seams`: the
      // surface around the ray is closed, see gf_trace), neither chart's patches reach it:
      // accept the border point when the line passes within one texel of it, moved onto the
      // line. At an open boundary of the surface this would be a false hit.
      float texel = max(dot(pu, pu), dot(pv, pv));
      if (seams && dot(r, r) <= texel) {
        p -= r.x * e1 + r.y * e2;
        uv = (x + 0.5f) / float(n);
        return true;
      }
      return false;
    }
    vec2 delta = vec2(j22 * r.x - j12 * r.y, j11 * r.y - j21 * r.x) / -det;
    float delta_length = sqrt(dot(delta, delta));
    if (delta_length > GF_NEWTON_MAX_STEP) {
      delta *= GF_NEWTON_MAX_STEP / delta_length;
    }
    x = clamp(x + delta, vec2(0.0f), vec2(float(n - 1)));
  }
  return false;
}

// The first hit (last = false) or the last hit (last = true: the field read from the exit side,
// i.e. the reversed line) of o + t d, t in [t_min, t_max], in mesh coordinates.
//   GF_MODE_NEAREST: the stored uv of the nearest entry and exit samples.
//   GF_MODE_LINEAR:  the paper's linear kernel over the 16 surrounding sample pairs (4 entry x 4
//                    exit samples, quadrilinear weights): a hit when the pairs that hit carry at
//                    least half the weight; uv = their weighted mean.
//   GF_MODE_REFINED: every hit uv of the 16 pairs is refined with gf_refine against the ray; the
//                    nearest (or, for `last`, farthest) verified intersection in [t_min, t_max].
GfHit gf_trace(vec3 o, vec3 d, float t_min, float t_max, int mode, bool last) {
  GfHit result = gf_miss();
  if (!(dot(d, d) > 0.0f)) {
    return result;  // zero or NaN direction
  }
  vec3 box_min = gf_box_min();
  vec3 extent = gf_box_max() - box_min;
  vec3 ou = (o - box_min) / extent;
  vec3 du = d / extent;
  float t0;
  float t1;
  int f0;
  int f1;
  if (!gf_clip_unit_cube(ou, du, t0, t1, f0, f1) || t1 < t_min || t0 > t_max) {
    return result;
  }
  int face_entry = last ? f1 : f0;
  int face_exit = last ? f0 : f1;
  if (face_entry == face_exit) {
    return result;
  }
  vec2 st_entry = gf_face_coords(face_entry, ou + (last ? t1 : t0) * du);
  vec2 st_exit = gf_face_coords(face_exit, ou + (last ? t0 : t1) * du);
  int n = gf_samples_per_side();
  if (mode == GF_MODE_NEAREST) {
    vec2 uv = gf_field_texel(gf_nearest_sample(face_entry, st_entry, n),
                             gf_nearest_sample(face_exit, st_exit, n));
    return uv.x >= 0.0f ? gf_hit_at(o, d, t_min, t_max, uv) : result;
  }
  ivec4 k_entry;
  ivec4 k_exit;
  vec4 w_entry;
  vec4 w_exit;
  gf_sample_cell(face_entry, st_entry, n, k_entry, w_entry);
  gf_sample_cell(face_exit, st_exit, n, k_exit, w_exit);
  if (mode == GF_MODE_LINEAR) {
    float weight = 0.0f;
    vec2 uv_sum = vec2(0.0f);
    for (int i = 0; i < 4; i++) {
      for (int j = 0; j < 4; j++) {
        vec2 uv = gf_field_texel(k_entry[i], k_exit[j]);
        if (uv.x >= 0.0f) {
          weight += w_entry[i] * w_exit[j];
          uv_sum += (w_entry[i] * w_exit[j]) * uv;
        }
      }
    }
    return weight >= 0.5f ? gf_hit_at(o, d, t_min, t_max, uv_sum / weight) : result;
  }
  // Refined: an orthonormal basis of the plane orthogonal to d (Duff et al. 2017).
  vec3 dn = normalize(d);
  float s = dn.z >= 0.0f ? 1.0f : -1.0f;
  float ka = -1.0f / (s + dn.z);
  float kb = dn.x * dn.y * ka;
  vec3 e1 = vec3(1.0f + s * dn.x * dn.x * ka, s * kb, -s * dn.x);
  vec3 e2 = vec3(kb, s + dn.y * dn.y * ka, -dn.y);
  float tolerance = GF_NEWTON_TOLERANCE * sqrt(dot(extent, extent));
  // The candidates, and the weight of the pairs that hit: when nearly all of the neighbourhood
  // hits, the surface around the ray is closed and a chart border there is a seam.
  vec2 candidates[16];
  float weight = 0.0f;
  for (int i = 0; i < 4; i++) {
    for (int j = 0; j < 4; j++) {
      candidates[4 * i + j] = gf_field_texel(k_entry[i], k_exit[j]);
      if (candidates[4 * i + j].x >= 0.0f) {
        weight += w_entry[i] * w_exit[j];
      }
    }
  }
  bool seams = weight >= GF_SEAM_WEIGHT;
  for (int i = 0; i < 4; i++) {
    for (int j = 0; j < 4; j++) {
      vec2 uv = candidates[4 * i + j];
      if (uv.x < 0.0f) {
        continue;
      }
      vec3 p;
      if (!gf_refine(o, e1, e2, tolerance, seams, uv, p)) {
        continue;
      }
      float t = dot(p - o, d) / dot(d, d);
      if (t < t_min || t > t_max) {
        continue;
      }
      if (!result.hit || (last ? t > result.t : t < result.t)) {
        result.hit = true;
        result.t = t;
        result.uv = uv;
        result.position = p;
      }
    }
  }
  if (result.hit) {
    result.normal = gf_image_normal(result.uv);
  }
  return result;
}
