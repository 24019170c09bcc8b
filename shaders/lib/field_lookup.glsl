// Geometry-field lookup (Li et al. 2006, section 3.2 step 1), with the `refined` mode (candidates
// verified against the geometry image by Newton's method) and the lookup beyond a ray's origin
// over a line's stored hits (docs/geometry-field.md, "Lookup").
//
// ONE source for the CPU and the GPU, in the CPU/GPU dialect (docs/architecture.md, "The CPU/GPU
// dialect"; float): included by core/src/field_lookup.cpp (inside a struct whose members supply
// the fetches below) and by the runtime's shaders.
//
// The includer includes field_lines.glsl before this file (the hits of a line: gf_line_hit, with
// the fetches it needs) and defines, before including this file (GLSL) or as members (C++):
//   int  gf_field_layers();                 K, the hits looked up per line at most
//   int  gf_image_size();                    n of the geometry image (n >= 2)
//   vec4 gf_image_texel(int i, int j);       position texel, column i, scanline j (texelFetch):
//                                            xyz P, w coverage A (> 0: surface, 0: padding)
//   vec3 gf_image_normal_texel(int i, int j);    normal texel (texelFetch)
//   vec3 gf_box_min();  vec3 gf_box_max();   the box (mesh coordinates) mapped to the unit cube
//
// Bilinear filtering is done here from 4 texelFetches (GL_LINEAR + GL_CLAMP_TO_EDGE semantics,
// texel centres at (i + 0.5) / n) rather than by the texture unit, whose 8-bit filter weights
// would make the GPU differ from the CPU. All math is float.
//
// Conventions (docs/geometry-field.md): rays are origin + t * direction in mesh (object)
// coordinates, t in [t_min, t_max]; a hit's t is along the given (unnormalised) direction.

// Work counting (shaders/lib/work.glsl): the includer may define GF_COUNT(kind, n) to count the
// lookups and the Newton steps; by default it is nothing.
#ifndef GF_COUNT
#define GF_COUNT(kind, n)
#endif

// The modes, GF_MODE_NEAREST, GF_MODE_LINEAR and GF_MODE_REFINED: contract.glsl.

// Newton iterations per candidate, the longest Newton step (texels of the geometry image), and
// the residual (distance between the line and the surface point, in box diagonals) accepted as
// an intersection.
GF_CONST int GF_NEWTON_ITERATIONS = 16;
GF_CONST float GF_NEWTON_MAX_STEP = 8.0f;
GF_CONST float GF_NEWTON_TOLERANCE = 1.0e-5f;
// A Newton search stalls at a step where its squared residual stays above half the last one; it
// gives up after GF_NEWTON_STALLS stalls in a row (near a root Newton's method converges
// quadratically; a line passing beside the surface makes no such progress).
GF_CONST int GF_NEWTON_STALLS = 2;
// Least weight of the hitting pairs among the 16 for a chart border to count as a seam.
GF_CONST float GF_SEAM_WEIGHT = 0.999f;
// Least weight of the hitting pairs among the 16 for the refined lookup to search every candidate
// on its own once its groups found no hit (half the linear kernel's threshold for a hit). Below it
// the neighbourhood says miss, and a ray there that hits is one the groups' searches found.
GF_CONST float GF_PAIRS_WEIGHT = 0.25f;
// A point at a chart border (across a seam, or on a patch with padding corners) is accepted only
// when the ray's start lies farther than this many texels off the surface's tangent plane there:
// a ray leaving the surface next to a chart border runs within a texel of the border's patches
// near its start, which are the surface it leaves, not a surface it hits.
GF_CONST float GF_SEAM_CLEARANCE = 2.0f;
// Rays starting inside the box, nearest and linear modes: a stored hit counts as beyond the
// ray's origin only when it projects onto the ray at least this many sample spacings (box
// diagonal / N) beyond t_min. A pair's line passes up to half a spacing beside the ray, so the
// unverified stored hit of the surface a ray leaves can project beyond its origin.
GF_CONST float GF_UNVERIFIED_MARGIN = 0.5f;
// Crossings of the surface a ray leaves that gf_trace_leaving looks beyond at most.
GF_CONST int GF_SELF_CROSSINGS = 2;
// The refined lookup groups candidates that lie within GF_GROUP_REACH (uv, max norm) of a group's
// first: a 16th of the image. The 16 pairs' lines lie a sample spacing apart, and where they hit
// one surface their uvs spread over a part of the image that depends on the surface, not on the
// image's resolution.
GF_CONST float GF_GROUP_REACH = 0.0625f;
// Once the refined lookup has verified a hit, a start whose surface point lies beyond it along the
// ray by more than this many sample spacings is not searched.
GF_CONST float GF_PRUNE_SPACINGS = 1.0f;

struct GfHit {
  bool hit;       // false: miss (or an invalid ray)
  float t;        // ray parameter of the hit
  vec2 uv;        // geometry-image uv of the hit
  vec3 position;  // mesh coordinates
  vec3 normal;    // unit normal from the geometry image
  bool doubt;     // an any-hit miss of the refined lookup that may be wrong (gf_trace_refined)
};

GfHit gf_miss() {
  GfHit h;
  h.hit = false;
  h.t = 0.0f;
  h.uv = vec2(-1.0f);
  h.position = vec3(0.0f);
  h.normal = vec3(0.0f);
  h.doubt = false;
  return h;
}

// Texel-centre coordinates of uv, clamped to the centres: the texel grid x in [0, n-1]^2.
vec2 gf_image_grid(vec2 uv, int n) {
  return clamp(uv * float(n) - 0.5f, vec2(0.0f), vec2(float(n - 1)));
}

// Lower-left texel of the bilinear patch holding grid point x.
ivec2 gf_image_cell(vec2 x, int n) {
  return min(ivec2(floor(x)), ivec2(n - 2));
}

// Bilinear position at uv (GL_LINEAR, GL_CLAMP_TO_EDGE).
vec3 gf_image_position(vec2 uv) {
  int n = gf_image_size();
  vec2 x = gf_image_grid(uv, n);
  ivec2 c = gf_image_cell(x, n);
  vec2 f = x - vec2(c);
  vec3 a = mix(vec3(gf_image_texel(c.x, c.y)), vec3(gf_image_texel(c.x + 1, c.y)), f.x);
  vec3 b = mix(vec3(gf_image_texel(c.x, c.y + 1)), vec3(gf_image_texel(c.x + 1, c.y + 1)), f.x);
  return mix(a, b, f.y);
}

// The position of the texel nearest to uv: one fetch, within half a texel's size of the
// bilinear position; enough to place a stored hit along a ray.
vec3 gf_image_position_nearest(vec2 uv) {
  int n = gf_image_size();
  ivec2 c = ivec2(floor(gf_image_grid(uv, n) + 0.5f));
  return vec3(gf_image_texel(c.x, c.y));
}

// Bilinear normal at uv, renormalised.
vec3 gf_image_normal(vec2 uv) {
  int n = gf_image_size();
  vec2 x = gf_image_grid(uv, n);
  ivec2 c = gf_image_cell(x, n);
  vec2 f = x - vec2(c);
  vec3 a = mix(gf_image_normal_texel(c.x, c.y), gf_image_normal_texel(c.x + 1, c.y), f.x);
  vec3 b = mix(gf_image_normal_texel(c.x, c.y + 1), gf_image_normal_texel(c.x + 1, c.y + 1), f.x);
  return normalize(mix(a, b, f.y));
}

// Clips the line o + t d (unit-cube coordinates) against the unit cube. t0/t1: entry and exit
// parameters; f0/f1: entry and exit faces (2 * axis, + 1 for the max side: -X, +X, -Y, ...).
bool gf_clip_unit_cube(vec3 o, vec3 d, GF_OUT(float) t0, GF_OUT(float) t1, GF_OUT(int) f0,
                       GF_OUT(int) f1) {
  t0 = -GF_FAR;
  t1 = GF_FAR;
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

// The hit at ray parameter t, geometry-image uv and point p, its normal from the image.
GfHit gf_hit(float t, vec2 uv, vec3 p) {
  GfHit h;
  h.hit = true;
  h.t = t;
  h.uv = uv;
  h.position = p;
  h.normal = gf_image_normal(uv);
  h.doubt = false;
  return h;
}

// A hit at geometry-image uv for the ray o + t d: position and normal from the image, t by
// projection onto the ray; a miss when t falls outside [t_min, t_max].
GfHit gf_hit_at(vec3 o, vec3 d, float t_min, float t_max, vec2 uv) {
  vec3 p = gf_image_position(uv);
  float t = dot(p - o, d) / dot(d, d);
  if (t < t_min || t > t_max) {
    return gf_miss();
  }
  return gf_hit(t, uv, p);
}

// Whether a chart-border point p (at uv, patches of squared size `texel`) is clear of the ray's
// start: the start lies more than GF_SEAM_CLEARANCE texels off the tangent plane at p.
bool gf_clear_of_start(vec2 uv, vec3 p, vec3 start, float texel) {
  float height = dot(gf_image_normal(uv), p - start);
  return height * height > GF_SEAM_CLEARANCE * GF_SEAM_CLEARANCE * texel;
}

// Covered corners (0..4) of a patch, from its 4 texels' coverage.
int gf_patch_coverage(vec4 coverage) {
  int covered = coverage.x > 0.0f ? 1 : 0;
  covered += coverage.y > 0.0f ? 1 : 0;
  covered += coverage.z > 0.0f ? 1 : 0;
  covered += coverage.w > 0.0f ? 1 : 0;
  return covered;
}

// How a Newton search (gf_refine) ended: without an intersection, on the line, or at a chart
// border across a seam (see gf_refine).
GF_CONST int GF_ENDED_APART = 0;
GF_CONST int GF_ENDED_ON_LINE = 1;
GF_CONST int GF_ENDED_AT_SEAM = 2;

// Whether the point where a Newton search ended (`ending`, at uv on a patch whose corners'
// coverage is `coverage`, texels of squared size `texel`) is an intersection, as gf_refine says;
// at a seam, p is moved onto the line by -r (its offset from the line in e1, e2).
bool gf_ended_on_surface(int ending, vec2 uv, vec4 coverage, float texel, vec3 start, vec2 r,
                         vec3 e1, vec3 e2, GF_INOUT(vec3) p) {
  int covered = gf_patch_coverage(coverage);
  if (ending == GF_ENDED_ON_LINE && covered == 4) {
    return true;
  }
  bool clear = gf_clear_of_start(uv, p, start, texel);
  if (ending == GF_ENDED_AT_SEAM) {
    p -= r.x * e1 + r.y * e2;
    return clear;
  }
  return covered > 0 && clear;
}

// Newton's method for the intersection of the line through o (directions e1, e2 span the plane
// orthogonal to it) with the geometry image's surface of bilinear patches between texel centres.
// Starts at uv, moves across patches (steps of at most GF_NEWTON_MAX_STEP texels) and succeeds
// when the surface point p is within `tolerance` (mesh units) of the line; uv and p are then the
// intersection. A point on a patch of padding texels only is no intersection (padding copies
// other texels); one on a patch with padding corners (a chart's border strip) must be clear of
// `start` (gf_clear_of_start; `start`: the point the ray starts from). `seams`: also accept
// chart-border points across seams (see below), clear of `start` too.
bool gf_refine(vec3 o, vec3 e1, vec3 e2, float tolerance, bool seams, vec3 start, GF_INOUT(vec2) uv,
               GF_OUT(vec3) p) {
  int n = gf_image_size();
  vec2 x = gf_image_grid(uv, n);
  p = vec3(0.0f);
  // The patch's 4 texels, fetched when the walk enters it.
  ivec2 cell = ivec2(-1);
  vec4 t00 = vec4(0.0f);
  vec4 t10 = vec4(0.0f);
  vec4 t01 = vec4(0.0f);
  vec4 t11 = vec4(0.0f);
  float previous = GF_FAR;
  int stalls = 0;
  // How the walk ended (GF_ENDED_*; at a seam, r is p's offset from the line). The point's
  // checks follow the loop: a shader runs each fetch in a loop's body at every step (llvmpipe
  // runs every branch under a mask), the normal's once after it.
  int ending = GF_ENDED_APART;
  vec2 r = vec2(0.0f);
  float texel = 0.0f;
  for (int iteration = 0; iteration < GF_NEWTON_ITERATIONS; iteration++) {
    GF_COUNT(WORK_NEWTON_STEPS, 1);
    ivec2 c = gf_image_cell(x, n);
    if (c != cell) {
      cell = c;
      t00 = gf_image_texel(c.x, c.y);
      t10 = gf_image_texel(c.x + 1, c.y);
      t01 = gf_image_texel(c.x, c.y + 1);
      t11 = gf_image_texel(c.x + 1, c.y + 1);
    }
    vec2 f = x - vec2(c);
    vec3 p00 = vec3(t00);
    vec3 p10 = vec3(t10);
    vec3 p01 = vec3(t01);
    vec3 p11 = vec3(t11);
    vec3 a = mix(p00, p10, f.x);
    vec3 b = mix(p01, p11, f.x);
    p = mix(a, b, f.y);
    vec3 pu = mix(p10 - p00, p11 - p01, f.y);
    vec3 pv = b - a;
    r = vec2(dot(p - o, e1), dot(p - o, e2));
    texel = max(dot(pu, pu), dot(pv, pv));
    if (dot(r, r) <= tolerance * tolerance) {
      ending = GF_ENDED_ON_LINE;
      break;
    }
    float residual = dot(r, r);
    stalls = residual > 0.5f * previous ? stalls + 1 : 0;
    if (stalls >= GF_NEWTON_STALLS) {
      break;
    }
    previous = residual;
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
      ending = seams && dot(r, r) <= texel ? GF_ENDED_AT_SEAM : GF_ENDED_APART;
      break;
    }
    vec2 delta = vec2(j22 * r.x - j12 * r.y, j11 * r.y - j21 * r.x) / -det;
    float delta_length = sqrt(dot(delta, delta));
    if (delta_length > GF_NEWTON_MAX_STEP) {
      delta *= GF_NEWTON_MAX_STEP / delta_length;
    }
    x = clamp(x + delta, vec2(0.0f), vec2(float(n - 1)));
  }
  if (ending == GF_ENDED_APART) {
    return false;
  }
  uv = (x + 0.5f) / float(n);
  return gf_ended_on_surface(ending, uv, vec4(t00.w, t10.w, t01.w, t11.w), texel, start, r, e1,
                             e2, p);
}

// One lookup's line: the ray, its range, and its 2 x 2 entry and exit samples with weights (the
// nearest entry and exit samples in k_entry.x / k_exit.x for GF_MODE_NEAREST).
struct GfLine {
  vec3 o;
  vec3 d;
  float t_min;
  float t_max;
  bool last;    // the last hit: the table read from the exit side
  bool beyond;  // the range starts inside the box: layers before the origin are skipped
  bool any_hit;  // a shadow ray's: any hit in the range will do (GfHit.doubt)
  // Refined, beyond the origin: the crossings the ray can meet first. The hits of a line
  // through a closed surface alternate from its entry sample: entering the solid (layers 0, 2,
  // ...), leaving it (1, 3, ...). A ray starting in the open meets an entering crossing first
  // (parity 0), one starting inside the solid a leaving one (1); -1: unknown, any layer.
  int parity;
  float margin;  // GF_UNVERIFIED_MARGIN in units of t
  ivec4 k_entry;
  ivec4 k_exit;
  vec4 w_entry;
  vec4 w_exit;
};

// Where stored uv lies along the line's ray: the projection of its nearest texel (one fetch,
// within half a texel of the surface point), as a ray parameter t.
float gf_stored_t(GF_IN(GfLine) line, vec2 uv) {
  return dot(gf_image_position_nearest(uv) - line.o, line.d) / dot(line.d, line.d);
}

// The first layer from `layer` on whose stored hit of the pair (entry, exit) lies beyond the
// line's origin: its projection onto the ray at least t_min + margin (for `last`, whose layers
// run from the exit side: at most t_max - margin); the last layer K - 1 is taken as it is (K = 1
// is the single-layer lookup). uv: that layer's stored uv. -1 when the line has no further hit.
// `hits`: the pair's line as read so far (gf_line_unread() at first).
int gf_layer_beyond(GF_IN(GfLine) line, int layer, int entry, int exit, float margin,
                    GF_OUT(vec2) uv, GF_INOUT(GfLineHits) hits) {
  uv = vec2(-1.0f);
  for (int l = layer; l < gf_field_layers(); l++) {
    uv = gf_line_hit(entry, exit, l, hits);
    if (uv.x < 0.0f) {
      return -1;
    }
    if (!line.beyond || l == gf_field_layers() - 1) {
      return l;
    }
    float t = gf_stored_t(line, uv);
    if (line.last ? t <= line.t_max - margin : t >= line.t_min + margin) {
      return l;
    }
  }
  return -1;
}

// The first stored hit beyond the origin of the pair (entry, exit) whose first hit is uv (a hit):
// gf_layer_beyond without a margin, with layer 0 already read; (-1, -1) when none.
// With a known parity, only the layers of that parity count (the crossings of the surface the
// ray starts on, whatever their place, have the other one).
vec2 gf_first_beyond(GF_IN(GfLine) line, int entry, int exit, vec2 uv, GF_INOUT(GfLineHits) hits) {
  if (!line.beyond || gf_field_layers() == 1) {
    return uv;
  }
  int step = line.parity < 0 ? 1 : 2;
  for (int l = max(line.parity, 0); l < gf_field_layers(); l += step) {
    if (l > 0) {
      uv = gf_line_hit(entry, exit, l, hits);
      if (uv.x < 0.0f) {
        return uv;
      }
    }
    float t = gf_stored_t(line, uv);
    if (line.last ? t <= line.t_max : t >= line.t_min) {
      return uv;
    }
  }
  return vec2(-1.0f);
}

// GF_MODE_NEAREST: the first stored hit beyond the origin (GF_UNVERIFIED_MARGIN) of the nearest
// entry and exit samples.
GfHit gf_trace_nearest(GF_IN(GfLine) line) {
  vec2 uv;
  GfLineHits hits = gf_line_unread();
  if (gf_layer_beyond(line, 0, line.k_entry.x, line.k_exit.x, line.margin, uv, hits) < 0) {
    return gf_miss();
  }
  return gf_hit_at(line.o, line.d, line.t_min, line.t_max, uv);
}

// GF_MODE_LINEAR: the paper's linear kernel over the 16 pairs' first stored hits beyond the
// origin (GF_UNVERIFIED_MARGIN): a hit when the pairs that hit carry at least half the weight;
// uv = their weighted mean.
GfHit gf_trace_linear(GF_IN(GfLine) line) {
  float weight = 0.0f;
  vec2 uv_sum = vec2(0.0f);
  for (int i = 0; i < 4; i++) {
    for (int j = 0; j < 4; j++) {
      vec2 uv;
      GfLineHits hits = gf_line_unread();
      if (gf_layer_beyond(line, 0, line.k_entry[i], line.k_exit[j], line.margin, uv, hits) >= 0) {
        weight += line.w_entry[i] * line.w_exit[j];
        uv_sum += (line.w_entry[i] * line.w_exit[j]) * uv;
      }
    }
  }
  if (weight < 0.5f) {
    return gf_miss();
  }
  return gf_hit_at(line.o, line.d, line.t_min, line.t_max, uv_sum / weight);
}

// An orthonormal basis e1, e2 of the plane orthogonal to d (Duff et al. 2017).
void gf_orthogonal_basis(vec3 d, GF_OUT(vec3) e1, GF_OUT(vec3) e2) {
  vec3 dn = normalize(d);
  float s = dn.z >= 0.0f ? 1.0f : -1.0f;
  float ka = -1.0f / (s + dn.z);
  float kb = dn.x * dn.y * ka;
  e1 = vec3(1.0f + s * dn.x * dn.x * ka, s * kb, -s * dn.x);
  e2 = vec3(kb, s + dn.y * dn.y * ka, -dn.y);
}

// The candidate of pair (i, j) of the 2 x 2 entry and exit samples: its first stored hit beyond
// the origin, (-1, -1) when none; `hits` holds its line as read. `crossed`: whether its line
// hits the surface at all.
vec2 gf_pair_candidate(GF_IN(GfLine) line, int i, int j, GF_INOUT(GfLineHits) hits,
                       GF_OUT(bool) crossed) {
  hits = gf_line_unread();
  vec2 uv = gf_line_hit(line.k_entry[i], line.k_exit[j], 0, hits);
  crossed = uv.x >= 0.0f;
  if (!crossed) {
    return uv;
  }
  return gf_first_beyond(line, line.k_entry[i], line.k_exit[j], uv, hits);
}

// The 16 pairs' candidates in two groups: those within GF_GROUP_REACH (uv, max norm) of the
// first candidate, and those within that of the first candidate outside it. Away from
// silhouettes and seams the candidates agree, and one Newton search from the first group's
// weighted mean is the lookup; two groups are two surfaces (or two sides of a seam). Plain
// fields, no arrays: a shader compiler keeps them in registers, where groups in arrays (and the
// loops over them) made llvmpipe's lookup about twice as slow.
struct GfCandidates {
  vec3 sum0;   // group 0 (the nearer along the ray): xy, the weighted sum of its uvs; z,
               // their weight (0: empty)
  vec3 best0;  // group 0: xy, its heaviest uv; z, that one's weight
  vec3 sum1;   // group 1, as group 0
  vec3 best1;
  bool together;    // no candidate outside the two groups
  float weight;     // of the pairs whose line hits at all
  vec2 member[16];  // pair p's candidate (p = 4 * entry + exit; (-1, -1): none)
  int layer0;       // bit p: pair p's candidate is its line's first hit, the line not read
};

GfCandidates gf_no_candidates() {
  GfCandidates c;
  c.sum0 = vec3(0.0f);
  c.best0 = vec3(-1.0f);
  c.sum1 = vec3(0.0f);
  c.best1 = vec3(-1.0f);
  c.together = true;
  c.weight = 0.0f;
  c.layer0 = 0;
  return c;
}

// Adds candidate uv of weight w to group `sum`, `best`.
void gf_candidate_add(GF_INOUT(vec3) sum, GF_INOUT(vec3) best, vec2 uv, float w) {
  // A pair at a sample itself has weight 0: it still counts.
  sum += vec3((w + 1.0e-6f) * uv, w + 1.0e-6f);
  if (w > best.z) {
    best = vec3(uv, w);
  }
}

// Whether uv lies within `reach` (max norm) of `first`.
bool gf_within(vec2 uv, vec2 first, float reach) {
  vec2 off = abs(uv - first);
  return max(off.x, off.y) <= reach;
}

// The candidates of pairs first, first + stride, ... below end of the 16 (p = 4 * entry + exit),
// grouped; two groups in their order along the ray (placed by the texel nearest to their mean
// uv). One loop over the pairs, however many are read: a shader holds one copy of a pair's
// reading.
GfCandidates gf_gather_candidates(GF_IN(GfLine) line, int first, int end, int stride) {
  GfCandidates c = gf_no_candidates();
  vec2 first0 = vec2(-1.0f);
  vec2 first1 = vec2(-1.0f);
  float reach = GF_GROUP_REACH;
  for (int pair = first; pair < end; pair += stride) {
    int i = pair / 4;
    int j = pair % 4;
    GfLineHits hits;
    bool crossed;
    vec2 uv = gf_pair_candidate(line, i, j, hits, crossed);
    float w = line.w_entry[i] * line.w_exit[j];
    c.weight += crossed ? w : 0.0f;
    c.member[pair] = uv;
    c.layer0 |= uv.x >= 0.0f && hits.count < 0 ? 1 << pair : 0;
    if (uv.x < 0.0f) {
      continue;
    }
    if (c.sum0.z == 0.0f) {
      first0 = uv;
    }
    if (gf_within(uv, first0, reach)) {
      gf_candidate_add(c.sum0, c.best0, uv, w);
      continue;
    }
    if (c.sum1.z == 0.0f) {
      first1 = uv;
    }
    if (gf_within(uv, first1, reach)) {
      gf_candidate_add(c.sum1, c.best1, uv, w);
    } else {
      c.together = false;
    }
  }
  if (c.sum1.z > 0.0f) {
    vec3 p0 = gf_image_position_nearest(vec2(c.sum0.x, c.sum0.y) / c.sum0.z);
    vec3 p1 = gf_image_position_nearest(vec2(c.sum1.x, c.sum1.y) / c.sum1.z);
    float ahead = dot(p1 - p0, line.d);
    if (line.last ? ahead > 0.0f : ahead < 0.0f) {
      vec3 sum = c.sum0;
      vec3 best = c.best0;
      c.sum0 = c.sum1;
      c.best0 = c.best1;
      c.sum1 = sum;
      c.best1 = best;
    }
  }
  return c;
}

// The index (0..3) of the largest of w's components.
int gf_heaviest(vec4 w) {
  int k = 0;
  for (int i = 1; i < 4; i++) {
    if (w[i] > w[k]) {
      k = i;
    }
  }
  return k;
}

// The nearest pair: the heaviest entry and exit samples (p = 4 * entry + exit).
int gf_nearest_pair(GF_IN(GfLine) line) {
  return 4 * gf_heaviest(line.w_entry) + gf_heaviest(line.w_exit);
}

// Whether the line of the nearest pair crosses the surface with the other parity than
// line.parity's beyond line.margin from the ray's origin (its last stored hit, read from the
// exit sample). Within a sample spacing of a concave crease the line and the ray lie on different
// sides of the surface, and a lookup on the ray's side misses the hits the line meets on the
// other.
bool gf_other_side_beyond(GF_IN(GfLine) line) {
  int nearest = gf_nearest_pair(line);
  int entry = line.k_entry[nearest / 4];
  int exit = line.k_exit[nearest % 4];
  GfLineHits hits = gf_read_line(entry, exit);
  int last = min(hits.count, gf_field_layers()) - 1;
  if (last < 0 || last % 2 == line.parity) {
    return false;
  }
  vec2 uv = gf_line_hit(entry, exit, last, hits);
  return uv.x >= 0.0f && gf_stored_t(line, uv) >= line.t_min + line.margin;
}

// The refined lookup's search stages (gf_next_start), in order.
// The nearest pair's candidate (ranges from inside the box).
GF_CONST int GF_STAGE_NEAREST_PAIR = 0;
// Where the nearest pair has none, whether any of six pairs spread over the 16 has a candidate.
GF_CONST int GF_STAGE_SPREAD = 1;
GF_CONST int GF_STAGE_GROUP0 = 2;  // group 0's weighted mean, then its heaviest candidate
GF_CONST int GF_STAGE_GROUP0_BEST = 3;
GF_CONST int GF_STAGE_GROUP1 = 4;  // group 1 likewise
GF_CONST int GF_STAGE_GROUP1_BEST = 5;
GF_CONST int GF_STAGE_PAIRS = 6;  // every candidate on its own, the nearest verified hit wins
// GF_STAGE_SPREAD's pairs: 0, 3, 6, ..., 15, i.e. (0, 0), (0, 3), (1, 2), (2, 1), (3, 0), (3, 3):
// every entry sample's line to the exit sample across the cell from it, and the cell's two
// outermost parallel lines. A ray leaving the surface whose nearest pair's line has no crossing
// beyond its origin mostly meets nothing (rays leaving a mirror or inside glass); where none of
// these lines has one either, it is a miss without reading the 16. Chosen by bench_lookup_work's
// agreement with exact casts: the four lines of the diagonal or of the corners miss more hits.
GF_CONST int GF_SPREAD_STRIDE = 3;

// Where the refined lookup's search stands.
struct GfSearch {
  GfCandidates candidates;
  int stage;    // the next stage
  int from;     // the stage of the start returned last
  int pair;     // GF_STAGE_PAIRS: the next pair (4 * entry + exit)
  bool deeper;  // GF_STAGE_PAIRS: next, the second crossing after the candidate of `pair`
};

// The start returned last is done with: in GF_STAGE_PAIRS, not its next crossing either.
void gf_search_done_with_start(GF_INOUT(GfSearch) s) {
  s.pair += s.deeper ? 1 : 0;
  s.deeper = false;
}

// The start of a group's stage (group 0 or 1, `best`: its heaviest candidate, else its mean);
// false when the group is empty or its heaviest candidate lies within a texel of its mean.
bool gf_group_start(GF_IN(GfCandidates) c, int group, bool best, GF_OUT(vec2) uv) {
  vec3 sum = group == 0 ? c.sum0 : c.sum1;
  vec3 heaviest = group == 0 ? c.best0 : c.best1;
  vec2 mean = vec2(sum.x, sum.y) / sum.z;
  uv = best ? vec2(heaviest.x, heaviest.y) : mean;
  vec2 off = abs(vec2(heaviest.x, heaviest.y) - mean);
  return sum.z > 0.0f && (!best || max(off.x, off.y) > 1.0f / float(gf_image_size()));
}

// The next candidate searched on its own (GF_STAGE_PAIRS): each pair's, read again, one read
// from layer 0 also followed by the second crossing after it (the ray passed beside the part
// its line hits; crossings alternate).
bool gf_next_pair(GF_IN(GfLine) line, GF_INOUT(GfSearch) s, GF_OUT(vec2) uv) {
  while (s.pair < 16) {
    int i = s.pair / 4;
    int j = s.pair % 4;
    if (s.deeper) {
      GfLineHits hits = gf_line_unread();
      uv = gf_line_hit(line.k_entry[i], line.k_exit[j], 2, hits);
      s.deeper = false;
      s.pair++;
    } else {
      uv = s.candidates.member[s.pair];
      s.deeper = (s.candidates.layer0 & (1 << s.pair)) != 0;
      s.pair += s.deeper ? 0 : 1;
    }
    if (uv.x >= 0.0f) {
      return true;
    }
  }
  return false;
}

// The next uv a Newton search starts from (s.from: its stage); false when none is left. A range
// that starts inside the box tries the nearest pair's candidate alone first (reading the lines
// past the hits behind the origin costs most there); where that pair has none, the spread pairs
// (GF_STAGE_SPREAD) say whether any line near the ray has one. Then the 16 pairs' candidates:
// the groups in their order along the ray, each from its mean and, where its heaviest candidate
// lies more than a texel off that, from that one; then, where the pairs whose lines hit carry at
// least GF_PAIRS_WEIGHT, every candidate on its own.
bool gf_next_start(GF_IN(GfLine) line, GF_INOUT(GfSearch) s, GF_OUT(vec2) uv) {
  if (s.stage == GF_STAGE_NEAREST_PAIR && !line.beyond) {
    s.stage = GF_STAGE_GROUP0;
  }
  if (s.stage <= GF_STAGE_GROUP0) {
    // The nearest pair alone, the spread pairs, or the 16 (one reading of pairs for all).
    bool alone = s.stage == GF_STAGE_NEAREST_PAIR;
    int nearest = gf_nearest_pair(line);
    int first = alone ? nearest : 0;
    int end = alone ? nearest + 1 : 16;
    int stride = s.stage == GF_STAGE_SPREAD ? GF_SPREAD_STRIDE : 1;
    s.candidates = gf_gather_candidates(line, first, end, stride);
    if (alone) {
      bool none = s.candidates.sum0.z == 0.0f;
      s.stage = none ? GF_STAGE_SPREAD : GF_STAGE_GROUP0;
      s.from = GF_STAGE_NEAREST_PAIR;
      uv = vec2(s.candidates.best0.x, s.candidates.best0.y);
      return true;  // (-1, -1) when the pair has no candidate: no search, the spread pairs next
    }
    if (s.stage == GF_STAGE_SPREAD) {
      s.stage = GF_STAGE_GROUP0;
      uv = vec2(-1.0f);
      return s.candidates.sum0.z > 0.0f;  // no search; the 16 next, or none: a miss
    }
  }
  for (int stage = GF_STAGE_GROUP0; stage < GF_STAGE_PAIRS; stage++) {
    if (stage == s.stage) {
      s.stage++;
      int group = stage < GF_STAGE_GROUP1 ? 0 : 1;
      bool best = stage == GF_STAGE_GROUP0_BEST || stage == GF_STAGE_GROUP1_BEST;
      if (gf_group_start(s.candidates, group, best, uv)) {
        s.from = stage;
        return true;
      }
    }
  }
  s.from = GF_STAGE_PAIRS;
  return s.candidates.weight >= GF_PAIRS_WEIGHT && gf_next_pair(line, s, uv);
}

// GF_MODE_REFINED: Newton searches (gf_refine) from the starts of gf_next_start. The first hit
// verified in [t_min, t_max] from the nearest pair or a group (in order along the ray) is the
// answer; searched on their own, the nearest of the candidates' verified hits is. None is a
// miss, except for a ray inside the solid (line.parity 1): the nearest pair's stored hit, placed
// on the ray (gf_hit_at: about a texel off the surface). When nearly all of the neighbourhood's
// lines hit, the surface around the ray is closed and a chart border there is a seam (unknown for
// the nearest pair alone: no seams then). An any-hit lookup's miss may carry GfHit.doubt.
GfHit gf_trace_refined(GF_IN(GfLine) line, float diagonal) {
  vec3 e1;
  vec3 e2;
  gf_orthogonal_basis(line.d, e1, e2);
  float tolerance = GF_NEWTON_TOLERANCE * diagonal;
  vec3 start = line.o + (line.last ? line.t_max : line.t_min) * line.d;
  GfSearch s;
  s.candidates = gf_no_candidates();
  s.stage = GF_STAGE_NEAREST_PAIR;
  s.from = -1;
  s.pair = 0;
  s.deeper = false;
  // The nearest verified hit: its t, uv and point (its normal is read once, after the loop).
  bool found = false;
  float hit_t = 0.0f;
  vec2 hit_uv = vec2(-1.0f);
  vec3 hit_p = vec3(0.0f);
  float nearest_t = GF_FAR;
  vec2 nearest_pair = vec2(-1.0f);  // the nearest pair's candidate
  bool searched = false;
  vec2 uv;
  for (int visit = 0; visit < 4 + 32 + 2; visit++) {
    if (!gf_next_start(line, s, uv)) {
      break;
    }
    if (uv.x < 0.0f) {
      continue;
    }
    nearest_pair = s.from == GF_STAGE_NEAREST_PAIR ? uv : nearest_pair;
    // Once a hit is verified, a start whose surface point lies beyond it cannot lead to a nearer
    // one (GF_PRUNE_SPACINGS).
    if (found) {
      float t_start = gf_stored_t(line, uv);
      if ((line.last ? -t_start : t_start) > nearest_t + GF_PRUNE_SPACINGS * 2.0f * line.margin) {
        gf_search_done_with_start(s);
        continue;
      }
    }
    vec3 p;
    bool seams = s.from > GF_STAGE_NEAREST_PAIR && s.candidates.weight >= GF_SEAM_WEIGHT;
    searched = true;
    if (!gf_refine(line.o, e1, e2, tolerance, seams, start, uv, p)) {
      continue;
    }
    gf_search_done_with_start(s);  // a candidate that verified
    float t = dot(p - line.o, line.d) / dot(line.d, line.d);
    float along = line.last ? -t : t;
    if (t < line.t_min || t > line.t_max || along >= nearest_t) {
      continue;
    }
    found = true;
    hit_t = t;
    hit_uv = uv;
    hit_p = p;
    nearest_t = along;
    // The nearest pair's hit is the answer, and a group's when no candidate lies outside the
    // groups (the groups are in order along the ray: a hit of the first is the nearer).
    if (s.from == GF_STAGE_NEAREST_PAIR || (s.from < GF_STAGE_PAIRS && s.candidates.together)) {
      break;
    }
    // A group's hit: its heaviest candidate is not searched.
    s.stage = s.from == GF_STAGE_GROUP0 ? GF_STAGE_GROUP1 : s.stage;
    s.stage = s.from == GF_STAGE_GROUP1 ? GF_STAGE_PAIRS : s.stage;
  }
  if (!found && line.parity == 1 && nearest_pair.x >= 0.0f) {
    // A ray inside the solid meets the surface again: where no search verified a hit (they left
    // the image's charts, near their borders), the nearest pair's stored hit is the answer.
    return gf_hit_at(line.o, line.d, line.t_min, line.t_max, nearest_pair);
  }
  if (!found) {
    // An any-hit lookup on a known side doubts a miss after searches that verified nothing (the
    // ray passes near the surface), or where the nearest pair's line meets the surface beyond
    // the origin from the other side.
    GfHit miss = gf_miss();  // WebGL has no ?: of structs
    miss.doubt = line.any_hit && line.parity >= 0 &&
                 (searched || (line.beyond && !line.last && gf_other_side_beyond(line)));
    return miss;
  }
  return gf_hit(hit_t, hit_uv, hit_p);
}

// The first hit beyond the ray's origin (last = false) or the last hit before its end (last =
// true: the field read from the exit side, i.e. the reversed line) of o + t d, t in
// [t_min, t_max], in mesh coordinates, over the stored hits of all layers (see the modes above).
// `side`: where the ray starts, for the refined lookup of a range that starts inside the box: +1
// in the open, -1 inside the solid, 0 unknown (GfLine.parity). `any_hit`: GfLine.any_hit.
GfHit gf_trace_side(vec3 o, vec3 d, float t_min, float t_max, int mode, bool last, float side,
                    bool any_hit) {
  GF_COUNT(WORK_LOOKUPS, 1);
  if (!(dot(d, d) > 0.0f)) {
    return gf_miss();  // zero or NaN direction
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
    return gf_miss();
  }
  int face_entry = last ? f1 : f0;
  int face_exit = last ? f0 : f1;
  if (face_entry == face_exit) {
    return gf_miss();
  }
  vec2 st_entry = gf_face_coords(face_entry, ou + (last ? t1 : t0) * du);
  vec2 st_exit = gf_face_coords(face_exit, ou + (last ? t0 : t1) * du);
  int n = gf_samples_per_side();
  float diagonal = sqrt(dot(extent, extent));
  GfLine line;
  line.o = o;
  line.d = d;
  line.t_min = t_min;
  line.t_max = t_max;
  line.last = last;
  // A start within 10^-4 of the chord from the box face is on the face (box-face rays, t0 ~ 0).
  float face = 1.0e-4f * (t1 - t0);
  line.beyond = last ? t_max < t1 - face : t_min > t0 + face;
  line.parity = last || side == 0.0f ? -1 : (side > 0.0f ? 0 : 1);
  line.any_hit = any_hit;
  line.margin = GF_UNVERIFIED_MARGIN * diagonal / (float(n) * sqrt(dot(d, d)));
  if (mode == GF_MODE_NEAREST) {
    line.k_entry = ivec4(gf_nearest_sample(face_entry, st_entry, n));
    line.k_exit = ivec4(gf_nearest_sample(face_exit, st_exit, n));
    line.w_entry = vec4(1.0f, 0.0f, 0.0f, 0.0f);
    line.w_exit = vec4(1.0f, 0.0f, 0.0f, 0.0f);
    return gf_trace_nearest(line);
  }
  gf_sample_cell(face_entry, st_entry, n, line.k_entry, line.w_entry);
  gf_sample_cell(face_exit, st_exit, n, line.k_exit, line.w_exit);
  if (mode == GF_MODE_LINEAR) {
    return gf_trace_linear(line);
  }
  return gf_trace_refined(line, diagonal);
}

GfHit gf_trace(vec3 o, vec3 d, float t_min, float t_max, int mode, bool last) {
  return gf_trace_side(o, d, t_min, t_max, mode, last, 0.0f, false);
}

// The hit of o + t d, t in [t_min, t_max], on the surface near geometry-image uv (a hit found for
// a nearby parallel ray, e.g. by gf_trace from an origin moved off the surface): gf_refine from
// uv, without crossing seams; a miss when it does not converge or leaves the range.
GfHit gf_hit_near(vec3 o, vec3 d, float t_min, float t_max, vec2 uv) {
  vec3 e1;
  vec3 e2;
  gf_orthogonal_basis(d, e1, e2);
  vec3 extent = gf_box_max() - gf_box_min();
  float tolerance = GF_NEWTON_TOLERANCE * sqrt(dot(extent, extent));
  vec3 p;
  if (!gf_refine(o, e1, e2, tolerance, false, o + t_min * d, uv, p)) {
    return gf_miss();
  }
  return gf_hit_at(o, d, t_min, t_max, uv);
}

// The first hit of o + t d, t in [t_min, t_max], for a ray leaving the surface: o lies just off
// the surface (t_min: twice that), `self_origin` farther off it (the geometry image's ray
// offset; `self_t_min`: twice that, a ray parameter like t); `facing`: the sign of
// dot(normal, d) at the start (normals out of the solid: +1 for a ray leaving into the open, -1
// for one entering the solid). A hit of the ray itself beyond self_t_min is clear of the surface
// it leaves. A nearer one may be that surface seen through the image's deviation from the mesh:
// such a crossing faces the ray as the start does (the ray leaves the image's solid where it
// leaves the mesh's), and the lookup goes on beyond it; a crossing facing the other way is a hit
// (the surface curving back). Where that does not settle it, the hit of the parallel ray from
// self_origin beyond self_t_min is taken, moved onto the ray (refined mode: gf_hit_near; where
// that fails the ray passes beside it: a miss). `any_hit`: a shadow ray, for which any hit in the
// range will do: where the refined lookup on its side doubts its miss (GfHit.doubt: the ray
// passes near the surface, at a shadow's edge or a concave crease, or the geometry image's
// deviation from the mesh puts its start on the surface's other side), the lookup on either side
// (facing 0) answers, one of the GF_SELF_CROSSINGS + 2 lookups at most. On its side alone such
// rays lose self-shadows; on either side alone each lookup near the surface searches every
// candidate, the crossings of the surface it leaves.
// gf_trace_leaving when `leaving`, else gf_trace(o, d, t_min, t_max, mode, false). One call of
// gf_trace in a loop, so that a shader holds one copy of the lookup however it is used (each
// call is inlined: with a call per case the geometry-field method's shader held some two dozen
// copies, and llvmpipe ran even a scene without meshes 5x slower).
GfHit gf_trace_from(vec3 o, vec3 d, float t_min, float t_max, vec3 self_origin, float self_t_min,
                    float facing, int mode, bool leaving, bool any_hit) {
  float shift = dot(self_origin - o, d) / dot(d, d);
  vec3 start = o;
  float from = t_min;
  float to = t_max;
  bool parallel = false;  // looking up the parallel ray from self_origin
  int crossings = 0;
  float side = facing;  // the side looked up
  for (int i = 0; i < GF_SELF_CROSSINGS + 2; i++) {
    GfHit h = gf_trace_side(start, d, from, to, mode, false, leaving ? side : 0.0f, any_hit);
    if (!leaving) {
      return h;
    }
    if (parallel) {
      if (!h.hit) {
        return h;
      }
      if (mode != GF_MODE_REFINED) {
        h.t += shift;
        return h;
      }
      return gf_hit_near(o, d, t_min, t_max, h.uv);
    }
    if (h.hit && h.t >= self_t_min) {
      return h;
    }
    if (!h.hit && h.doubt && side != 0.0f) {
      side = 0.0f;
      continue;
    }
    if (!h.hit && mode == GF_MODE_REFINED) {
      return h;  // the refined lookup knew the side the ray starts on: no crossing is a miss
    }
    if (h.hit && crossings < GF_SELF_CROSSINGS) {
      if (side * dot(h.normal, d) < 0.0f) {
        return h;
      }
      from = h.t + t_min;
      crossings++;
    } else {
      parallel = true;
      start = self_origin;
      from = self_t_min;
      to = t_max - shift;
    }
  }
  return gf_miss();
}

GfHit gf_trace_leaving(vec3 o, vec3 d, float t_min, float t_max, vec3 self_origin, float self_t_min,
                       float facing, int mode, bool any_hit) {
  return gf_trace_from(o, d, t_min, t_max, self_origin, self_t_min, facing, mode, true, any_hit);
}

#ifdef __cplusplus
#undef GF_COUNT  // the includer's hook ends with this file (docs/architecture.md)
#endif
