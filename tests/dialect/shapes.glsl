// What the C++ includer of shaders/lib/shapes.glsl defines (its header), for the dialect test
// (scripts/check-glsl-dialect.py): its types and pi in double, as the reference tracer compiles
// it. GLSL needs nothing: the file defines them in float itself.
#ifdef __cplusplus
using real = double;
using rvec2 = dvec2;
using rvec3 = dvec3;
using rvec4 = dvec4;
constexpr real GF_PI = 3.14159265358979323846;
#endif
