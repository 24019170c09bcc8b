// What the includer of shaders/lib/field_lines.glsl defines (its header), for the dialect test
// (scripts/check-glsl-dialect.py): the fetches of a compact field, here of an empty one.
int gf_samples_per_side() { return 24; }
vec2 gf_field_nearest_texel(int entry, int column) { return vec2(-1.0f); }
uint gf_field_word(int i) { return 0u; }
vec2 gf_field_interior_texel(int i) { return vec2(0.0f); }
