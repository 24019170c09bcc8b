#pragma once
// Keys of mesh edges for hash maps: the one place that packs two vertex indices into 64 bits.

#include <algorithm>
#include <cstdint>

namespace gfield {

/// Key of the directed half-edge a -> b (vertex indices, 0 <= a, b < 2^32): a in the high 32
/// bits, b in the low.
inline uint64_t half_edge_key(int a, int b) {
  return (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
}

/// The half-edge's start and end vertices.
inline int half_edge_source(uint64_t key) {
  return int(uint32_t(key >> 32));
}
inline int half_edge_target(uint64_t key) {
  return int(uint32_t(key));
}

/// Key of the undirected edge {a, b}: the half-edge from the smaller index to the larger.
inline uint64_t edge_key(int a, int b) {
  return half_edge_key(std::min(a, b), std::max(a, b));
}

}  // namespace gfield
