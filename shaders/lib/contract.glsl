// The contract between the C++ runtime and the shaders, written once. This file is valid GLSL
// 4.50 and valid C++ with GLM: the shaders include it, and core/include/gfield/gpu_contract.hpp
// includes it into namespace gfield::gpu. It holds the codes both sides use (shapes, materials,
// textures, environments), the numbers both sides use (pi, the far sentinels, the glass method's
// layers), the binding slots of storage buffers and texture units, the std430 layouts of the scene
// buffers, and the camera ray. It is written in the CPU/GPU dialect (docs/architecture.md, "The
// CPU/GPU dialect"), with structs of vec4 / ivec4 / mat4 members only (their std430 layout is the
// C++ layout).

// The dialect's words in GLSL; C++ defines them in gfield/glsl_begin.hpp. GF_CONST: a constant;
// GF_INLINE: a function of this header; GF_IN(T), GF_OUT(T), GF_INOUT(T): a parameter passed in,
// out, in and out. `real` and its vectors: the precision of the files that C++ compiles in
// double (shapes.glsl, optics.glsl), float on the GPU.
#ifndef __cplusplus
#define GF_CONST const
#define GF_INLINE
#define GF_IN(T) in T
#define GF_OUT(T) out T
#define GF_INOUT(T) inout T
#define real float
#define rvec2 vec2
#define rvec3 vec3
#define rvec4 vec4
#endif

// pi, as a float.
GF_CONST float GF_PI = 3.14159265358979f;
// A distance beyond every hit (scene units or along a ray): the t_max of a ray without one, the
// t of a miss, the corners of empty bounds (-GF_FAR, GF_FAR).
GF_CONST float GF_FAR = 3.0e38f;
// The image-space methods' eye depth of a texel where nothing was drawn (shaders/lib/
// image_space.glsl; runtime/methods/image_space_refraction.cpp clears its maps to it).
GF_CONST float IS_FAR = 1.0e30f;

// Geometry-field lookup modes (gfield::LookupMode; field_lookup.glsl).
GF_CONST int GF_MODE_NEAREST = 0;
GF_CONST int GF_MODE_LINEAR = 1;
GF_CONST int GF_MODE_REFINED = 2;

// Shapes (gfield::ShapeType).
GF_CONST int SHAPE_MESH = 0;
GF_CONST int SHAPE_SPHERE = 1;
GF_CONST int SHAPE_QUAD = 2;
GF_CONST int SHAPE_BOX = 3;
GF_CONST int SHAPE_CYLINDER = 4;
GF_CONST int SHAPE_SLAB = 5;
GF_CONST int SHAPE_HOLLOW_CYLINDER = 6;

// Materials (gfield::MaterialType).
GF_CONST int MATERIAL_DIFFUSE = 0;
GF_CONST int MATERIAL_MIRROR = 1;
GF_CONST int MATERIAL_DIELECTRIC = 2;

// Procedural textures (gfield::TextureType).
GF_CONST int TEXTURE_NONE = 0;
GF_CONST int TEXTURE_CHECKER = 1;
GF_CONST int TEXTURE_COLOR_CHART = 2;
GF_CONST int TEXTURE_MESH = 3;  // the mesh's own base colour (texture, vertex or material colours)

// Environments (gfield::EnvironmentType).
GF_CONST int ENV_STUDIO = 0;
GF_CONST int ENV_CONSTANT = 1;
GF_CONST int ENV_EQUIRECT = 2;
GF_CONST int ENV_CUBE = 3;

// Smallest offset of a ray leaving a mesh's surface, in the mesh's box diagonals: the offset of
// rays leaving a point found by a field lookup, and the least geometry-image ray offset
// (gfield::GeometryImage::ray_offset, the offset of rays leaving a point of the rasterised mesh).
GF_CONST float GF_MIN_RAY_OFFSET = 1.0e-4f;

// Shader storage buffer bindings.
GF_CONST int BUFFER_OBJECTS = 0;        // GpuObject[], one per scene object
GF_CONST int BUFFER_LIGHTS = 1;         // GpuLight[], one per light
GF_CONST int BUFFER_BVH_NODES = 2;      // GpuBvhNode[]: every mesh's BVH, one after another
GF_CONST int BUFFER_BVH_TRIANGLES = 3;  // GpuBvhTriangle[]: their triangles in leaf order
GF_CONST int BUFFER_BVH_SHADING = 4;    // GpuBvhShading[]: the same triangles' shading data
GF_CONST int BUFFER_WORK = 5;           // uint[WORK_COUNT]: work counters (GF_COUNT_WORK)
GF_CONST int BUFFER_FIELD_LINES = 6;    // uint[]: every field's line table and interior hits

// Work counters (runtime/work_counters.hpp), summed over a frame's fragments: what a lookup or a
// traversal costs, independent of the device.
GF_CONST int WORK_LOOKUPS = 0;           // geometry-field lookups (gf_trace)
GF_CONST int WORK_FIELD_FETCHES = 1;     // field texels read
GF_CONST int WORK_IMAGE_FETCHES = 2;     // geometry-image texels read (positions, normals, ...)
GF_CONST int WORK_NEWTON_STEPS = 3;      // iterations of gf_refine
GF_CONST int WORK_BVH_TRAVERSALS = 4;    // BVH traversals (gb_trace)
GF_CONST int WORK_BVH_NODES = 5;         // BVH nodes whose bounds were tested
GF_CONST int WORK_BVH_TRIANGLES = 6;     // triangles tested
GF_CONST int WORK_RAYS = 7;              // secondary rays traced (the field method's stack)
GF_CONST int WORK_COUNT = 8;

// The glass method (runtime/methods/glass.*, shaders/glass_*): the glass surfaces depth peeling
// keeps per pixel (units UNIT_PEEL_LAYERS + k), the refraction classes (a scene image each at
// most), and the directional lights with a shadow map.
GF_CONST int GLASS_LAYERS = 4;
GF_CONST int GLASS_CLASSES = 8;
GF_CONST int GLASS_SHADOWED_LIGHTS = 4;

// Texture units. Every program of the runtime draws from this one table, so a unit means the
// same texture in every pass.
GF_CONST int UNIT_GI_POSITIONS = 0;   // 2D array RGBA32F: P (mesh coordinates), coverage A in w
GF_CONST int UNIT_GI_NORMALS = 1;     // 2D array RGBA32F: unit normals
GF_CONST int UNIT_FIELDS = 2;         // 2D array RG8/RG16/RG32F: nearest-hit uv codes, texel
                                      // (column, entry), a field per layer
GF_CONST int UNIT_PROBE_ORIGINS = 3;  // field probe: ray origins (xyz) and t_min (w)
GF_CONST int UNIT_PROBE_DIRECTIONS = 4;  // field probe: ray directions (xyz) and t_max (w)
GF_CONST int UNIT_ENVIRONMENT = 5;    // 2D array RGBA32F: equirect layer 0 or six cube faces
GF_CONST int UNIT_GBUFFER_POSITION = 6;   // xyz world position, w object (-1: none)
GF_CONST int UNIT_GBUFFER_NORMAL = 7;     // xyz shading normal, w texture u
GF_CONST int UNIT_GBUFFER_GEOMETRIC = 8;  // xyz geometric normal, w texture v
GF_CONST int UNIT_THICKNESS = 9;      // 2D array R32F: d_n per geometry-image texel (wyman2005)
GF_CONST int UNIT_CUBE = 10;          // the cube map of the object being drawn (cubemap, envmap)
GF_CONST int UNIT_BACK = 11;          // back faces of the refractors: normal, eye depth
GF_CONST int UNIT_FRONT = 12;         // front faces of the refractors: normal, eye depth
GF_CONST int UNIT_NEARBY = 13;        // nearby geometry: colour, eye depth
GF_CONST int UNIT_PEEL_PREVIOUS = 14;  // glass, while peeling: the layer peeled before
GF_CONST int UNIT_PEEL_LAYERS = 15;    // glass: peeled layer k in unit 15 + k, k < GLASS_LAYERS
GF_CONST int UNIT_CLASS_IMAGES = UNIT_PEEL_LAYERS + GLASS_LAYERS;  // 19: glass: 2D array, one
                                                                  // scene image per class
GF_CONST int UNIT_SHADOW_MAPS = 20;    // glass: 2D array shadow maps, layer = light
GF_CONST int UNIT_FRAME = 21;          // the presented frame (viewer)
GF_CONST int UNIT_GI_ALBEDO = 22;      // 2D array RGBA16F: geometry-image albedo (linear rgb)
GF_CONST int UNIT_MESH_TEXTURES = 23;  // 2D array RGBA16F: the meshes' own textures (linear
                                       // rgb, row 0 at v = 0), bilinear, repeating
GF_CONST int UNIT_GBUFFER_ALBEDO = 24;  // rgb albedo of the first hit (diffuse surfaces)
GF_CONST int UNIT_PROBE_SELF = 25;  // field probe, rays leaving the surface: the origin of their
                                    // own lookup (xyz) and the side they leave on (w: facing)
// Units in all: every unit above is below it, and no two are the same (tests/core/
// gpu_contract_test.cpp checks both at compile time).
GF_CONST int UNIT_COUNT = 26;

// Scenes of at most this many objects are traced with each object's order key computed once
// per ray (GF_CACHED_ENTRIES, shaders/lib/scene.glsl: trace_scene).
GF_CONST int SCENE_CACHED_ENTRIES = 16;

// The web player (docs/web.md): WebGL2 has no storage buffers. The objects and lights are
// uniform blocks of at most these many (std140: 48 GpuObjects fill 15 of the 16 KB every WebGL2
// block may hold), the fields' words an R32UI texture and the BVHs RGBA32F textures, in rows of
// WEB_TEXEL_ROW texels.
GF_CONST int WEB_MAX_OBJECTS = 48;
GF_CONST int WEB_MAX_LIGHTS = 16;
GF_CONST int WEB_TEXEL_ROW = 4096;

// Image units (image load/store): the field method's compute tracing pass writes the frame.
GF_CONST int IMAGE_TRACE_COLOR = 0;  // RGBA32F: linear radiance, alpha 1
GF_CONST int IMAGE_TRACE_HITS = 1;   // RGBA32F: first hit object, secondary rays traced, 0, 0

// Geometry-field texels on the GPU (runtime/gpu_assets): each uv component as a normalised
// integer of `bits` bits (8: RG8, 16: RG16; 32: RG32F, the float as is). A uv in [0,1] is the
// code round(uv * (2^bits - 3)); code 2^bits - 2 stands for "no ray" (-2), 2^bits - 1 for a
// miss (-1). The texture unit returns code / (2^bits - 1).
GF_INLINE float gf_encode_field_component(float uv, int bits) {
  float top = float((1 << bits) - 1);
  if (uv < -1.5f) return top - 1.0f;
  if (uv < 0.0f) return top;
  return round(min(uv, 1.0f) * (top - 2.0f));
}
// A component's code (an integer, bits < 32) as a uv component, -1 or -2.
GF_INLINE float gf_decode_field_code(float code, int bits) {
  float top = float((1 << bits) - 1);
  if (code > top - 0.5f) return -1.0f;
  if (code > top - 1.5f) return -2.0f;
  return code / (top - 2.0f);
}
GF_INLINE float gf_decode_field_component(float texel, int bits) {
  if (bits >= 32) return texel;
  return gf_decode_field_code(round(texel * float((1 << bits) - 1)), bits);
}
GF_INLINE vec2 gf_decode_field_texel(vec2 texel, int bits) {
  return vec2(gf_decode_field_component(texel.x, bits), gf_decode_field_component(texel.y, bits));
}

// The compact geometry field (format version 3; docs/formats.md, "Geometry field"). Each line
// through two samples on different faces holds its hits h1..hn in order from its lower sample
// index (at most FIELD_MAX_LINE_HITS: a line with more keeps the 4 nearest each end).
// - The nearest-hit table: for every ordered pair (entry, exit) on different faces, the hit
//   nearest the entry (h1 from the lower sample, hn from the higher), or a miss; (6N^2) rows (the
//   entry sample) of 5N^2 columns (the exit sample among the five other faces:
//   gf_field_column).
// - The line table, uint words: the lines of 1 hit or of 3 or more (a line without an entry
//   holds 0 or 2: its nearest hits), by tiles of FIELD_TILE x FIELD_TILE lines of the table
//   (row = the lower sample, column = the higher one's). Words [0, tiles): 0, or the word where
//   the tile's record starts; a record: 64 bits of which lines have an entry (slot
//   gf_field_tile_slot; words 0 and 1), the half-word index of the tile's first entry (word 2)
//   and the index of its first interior hit (word 3). Entries are 16 bits, two per word (the
//   first in the low half), in slot order: the hit count n (bits 0-3) and the offset of the
//   line's interior hits h2..h(n-1) from the record's first (bits 4-15).
// - The interior hits, in order from each line's lower sample.
GF_CONST int FIELD_MAX_LINE_HITS = 8;
GF_CONST int FIELD_TILE = 8;
// Columns of the nearest-hit table: 5 N^2.
GF_INLINE int gf_field_columns(int n) { return 5 * n * n; }
// The column of exit sample `exit` in entry sample `entry`'s row (their faces differ, so the
// exit's face comes after the entry's exactly when exit > entry): no division, which llvmpipe
// runs lane by lane.
GF_INLINE int gf_field_column(int n, int entry, int exit) {
  return exit > entry ? exit - n * n : exit;
}
// Tiles per row of the line table, and tiles in all: the words before the records.
GF_INLINE int gf_field_tile_columns(int n) { return (5 * n * n + FIELD_TILE - 1) / FIELD_TILE; }
GF_INLINE int gf_field_tiles(int n) {
  return (6 * n * n + FIELD_TILE - 1) / FIELD_TILE * gf_field_tile_columns(n);
}
// The tile of the line (low, high) at `column` = gf_field_column(n, low, high), and its slot.
GF_INLINE int gf_field_tile(int n, int low, int column) {
  return low / FIELD_TILE * gf_field_tile_columns(n) + column / FIELD_TILE;
}
GF_INLINE int gf_field_tile_slot(int low, int column) {
  return low % FIELD_TILE * FIELD_TILE + column % FIELD_TILE;
}

// One scene object (std430, 320 bytes).
struct GpuObject {
  mat4 to_world;    // object -> world
  mat4 to_object;   // world -> object
  vec4 color;       // rgb: albedo or mirror tint; w: index of refraction
  vec4 absorption;  // rgb: Beer-Lambert coefficient; w: world diagonal of the object's bounds
  vec4 checker0;    // rgb: first checker colour; w: squares along u
  vec4 checker1;    // rgb: second checker colour; w: squares along v
  vec4 shape;       // radius, height, thickness, 0
  vec4 size;        // xyz: box / quad / slab extents
  vec4 box_min;     // xyz: object-space bounds (mesh: the asset's box, mesh coordinates);
                    // w: mesh: its geometry image's ray offset (box diagonals)
  vec4 box_max;
  ivec4 kind;   // SHAPE_*, MATERIAL_*, TEXTURE_*, 0
  ivec4 asset;  // mesh: image layer, samples per side N, geometry-image size n, 1 when the
                // geometry image holds albedo (UNIT_GI_ALBEDO) else 0
  ivec4 field;  // mesh: its layer in the nearest-hit array (UNIT_FIELDS), the first word of
                // its line table and of its interior hits in BUFFER_FIELD_LINES, bits per uv
                // component + 256 * the hits a lookup reads per line (GeometryField::layers)
  ivec4 image;  // mesh: texel (x, y) of its geometry image's corner in layer asset.x (images
                // share layers: runtime/image_atlas.hpp); z: the root of its BVH in
                // BUFFER_BVH_NODES (-1: none loaded); w: 1 when it is traced through its BVH
                // although it has a field (--intersect auto), else 0
};

// One BVH node (std430, 32 bytes; geometry/mesh_bvh.hpp), bounds in mesh coordinates. The
// integers are stored as float bits (floatBitsToInt).
struct GpuBvhNode {
  vec4 lo;  // xyz: bounds min; w: inner node: its left child (the right one follows it); leaf:
            // its first triangle in BUFFER_BVH_TRIANGLES
  vec4 hi;  // xyz: bounds max; w: the leaf's triangles (0: an inner node)
};

// One triangle of a BVH (std430, 48 bytes), mesh coordinates.
struct GpuBvhTriangle {
  vec4 p0;  // xyz: corner 0; w: the layer of its texture in UNIT_MESH_TEXTURES (-1: none)
  vec4 e1;  // xyz: corner 1 - corner 0
  vec4 e2;  // xyz: corner 2 - corner 0
};

// What shades a BVH triangle's hit (std430, 96 bytes): per corner, the shading normal (mesh
// coordinates) with texture u, and the base colour (the mesh's material colour x vertex colour,
// linear) with texture v: the rasterised mesh's vertex attributes (runtime/gpu_assets.hpp).
struct GpuBvhShading {
  vec4 normal_u0;
  vec4 normal_u1;
  vec4 normal_u2;
  vec4 base_v0;
  vec4 base_v1;
  vec4 base_v2;
};

// One light (std430, 48 bytes).
struct GpuLight {
  vec4 direction;  // xyz: the way a directional light travels; w: 0 directional, 1 point
  vec4 position;   // xyz: point light position
  vec4 color;      // rgb: colour * intensity
};

// The camera ray's direction (world, unit) through `pixel` (x right, y down, pixel centres at
// + 0.5) of a picture of `image_size` pixels, for a camera looking along `forward` with `right`
// and `up` (unit, orthogonal) and tan_half = (tan(fov / 2) * aspect, tan(fov / 2)): the ray of
// gfield::camera_ray.
GF_INLINE vec3 gf_camera_direction(vec3 forward, vec3 right, vec3 up, vec2 tan_half, vec2 image_size,
                                   vec2 pixel) {
  float sx = (2.0f * pixel.x / image_size.x - 1.0f) * tan_half.x;
  float sy = (1.0f - 2.0f * pixel.y / image_size.y) * tan_half.y;
  return normalize(forward + sx * right + sy * up);
}
