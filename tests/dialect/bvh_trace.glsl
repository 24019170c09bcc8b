// What the includer of shaders/lib/bvh_trace.glsl defines (its header), for the dialect test
// (scripts/check-glsl-dialect.py): the fetches of a BVH, here of one leaf of one triangle.
vec3 gb_node_lo(int i) { return vec3(0.0f); }
vec3 gb_node_hi(int i) { return vec3(1.0f); }
int gb_node_first(int i) { return 0; }
int gb_node_count(int i) { return 1; }
vec3 gb_triangle_p0(int s) { return vec3(0.0f); }
vec3 gb_triangle_e1(int s) { return vec3(1.0f, 0.0f, 0.0f); }
vec3 gb_triangle_e2(int s) { return vec3(0.0f, 1.0f, 0.0f); }
