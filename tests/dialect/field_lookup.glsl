// What the includer of shaders/lib/field_lookup.glsl defines (its header), for the dialect test
// (scripts/check-glsl-dialect.py): the fetches of field_lines.glsl and of a geometry image, here
// of an empty field and a flat image.
int gf_samples_per_side() { return 24; }
vec2 gf_field_nearest_texel(int entry, int column) { return vec2(-1.0f); }
uint gf_field_word(int i) { return 0u; }
vec2 gf_field_interior_texel(int i) { return vec2(0.0f); }
int gf_field_layers() { return 8; }
int gf_image_size() { return 512; }
vec4 gf_image_texel(int i, int j) { return vec4(float(i), float(j), 0.0f, 1.0f); }
vec3 gf_image_normal_texel(int i, int j) { return vec3(0.0f, 0.0f, 1.0f); }
vec3 gf_box_min() { return vec3(-1.0f); }
vec3 gf_box_max() { return vec3(1.0f); }
