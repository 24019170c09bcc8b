// Closes the CPU/GPU dialect that gfield/glsl_begin.hpp opened: its macros end here. Not
// guarded: it closes each pair.

#undef GF_CONST
#undef GF_INLINE
#undef GF_IN
#undef GF_OUT
#undef GF_INOUT
