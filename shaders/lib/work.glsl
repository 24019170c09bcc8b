// Work counters (the contract's WORK_*, runtime/work_counters.hpp): what a frame's lookups and
// traversals cost, counted per fragment into locals and added to BUFFER_WORK once, at the end of
// main() (work_flush), so that counting changes no result and no timing of a normal build:
// without GF_COUNT_WORK (a define of the counting build of a program) it compiles to nothing.

#include "lib/contract.glsl"

#ifdef GF_COUNT_WORK
#ifdef GL_ES
// WebGL2 has neither storage buffers nor atomics: each fragment writes its counts to two RGBA32UI
// attachments of the counting draw, which the page reads back and adds up
// (web/player/gfield-player.js, countWork).
// WORK_COUNT is 8: two uvec4 (web/player/gfield-player.js, WORK_COUNTERS, reads them in order).
layout(location = 2) out uvec4 o_work_low;   // WORK_LOOKUPS .. WORK_NEWTON_STEPS
layout(location = 3) out uvec4 o_work_high;  // WORK_BVH_TRAVERSALS .. WORK_RAYS
#else
layout(std430, binding = BUFFER_WORK) buffer Work { uint work_counters[]; };
#endif
uint work_local[WORK_COUNT] = uint[WORK_COUNT](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
#define WORK_ADD(kind, n) work_local[kind] += uint(n)
void work_flush() {
#ifdef GL_ES
  o_work_low = uvec4(work_local[0], work_local[1], work_local[2], work_local[3]);
  o_work_high = uvec4(work_local[4], work_local[5], work_local[6], work_local[7]);
#else
  for (int i = 0; i < WORK_COUNT; i++)
    if (work_local[i] != 0u) atomicAdd(work_counters[i], work_local[i]);
#endif
}
#else
#define WORK_ADD(kind, n)
void work_flush() {}
#endif
