#pragma once
// std::allocator whose value-initialisation is default-initialisation: resize() of a vector of
// a trivial type (floats, glm vectors) allocates without zeroing, as make_unique_for_overwrite
// does. For large tables that are written in full right after, by several threads: zeroing
// would touch every page once on one thread first (geometry field: 95 MB a layer at N = 24,
// 11% of a two-layer build).

#include <memory>
#include <new>
#include <utility>

namespace gfield {

template <class T>
struct UninitializedAllocator : std::allocator<T> {
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}

  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace gfield
