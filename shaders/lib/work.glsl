// Work counters (the contract's WORK_*, runtime/work_counters.hpp): what a frame's lookups and
// traversals cost, counted per fragment into locals and added to BUFFER_WORK once, at the end of
// main() (work_flush), so that counting changes no result and no timing of a normal build:
// without GF_COUNT_WORK (a define of the counting build of a program) it compiles to nothing.

#include "lib/contract.glsl"

#ifdef GF_COUNT_WORK
layout(std430, binding = BUFFER_WORK) buffer Work { uint work_counters[]; };
uint work_local[WORK_COUNT] = uint[WORK_COUNT](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u);
#define WORK_ADD(kind, n) work_local[kind] += uint(n)
void work_flush() {
  for (int i = 0; i < WORK_COUNT; i++)
    if (work_local[i] != 0u) atomicAdd(work_counters[i], work_local[i]);
}
#else
#define WORK_ADD(kind, n)
void work_flush() {}
#endif
