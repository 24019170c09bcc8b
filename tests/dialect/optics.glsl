// What the C++ includer of shaders/lib/optics.glsl defines (its header), for the dialect test
// (scripts/check-glsl-dialect.py): its types in double, as gfield/optics.hpp compiles it. GLSL
// needs nothing: contract.glsl defines them in float.
#ifdef __cplusplus
using real = double;
using rvec3 = dvec3;
#endif
