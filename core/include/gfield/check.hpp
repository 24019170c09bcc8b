#pragma once
// Checked invariants: what the code relies on, stated where it relies on it.
//
// GF_CHECK(condition, message): always on. What must hold whatever the input (a program's own
// mistake otherwise: a uniform no shader declares, tables out of step); when it does not, the
// process prints "FILE:LINE: check failed: CONDITION: MESSAGE" to stderr and aborts.
// GF_DCHECK(condition, message): the same in debug and sanitizer builds (no NDEBUG, or
// GFIELD_DCHECK defined); otherwise the condition is compiled but not evaluated. For checks on
// hot paths, such as index helpers (texel_index, field_nearest_index, GPU-scene objects).
//
// `message` is anything a std::string_view is made from; it is evaluated only on failure.

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace gfield::detail {

[[noreturn]] inline void check_failed(const char* file, int line, const char* condition,
                                      std::string_view message) {
  std::fprintf(stderr, "%s:%d: check failed: %s: %.*s\n", file, line, condition,
               int(message.size()), message.data());
  std::fflush(stderr);
  std::abort();
}

}  // namespace gfield::detail

#define GF_CHECK(condition, message)                                            \
  ((condition) ? void(0)                                                        \
               : ::gfield::detail::check_failed(__FILE__, __LINE__, #condition, \
                                                std::string_view(message)))

#if !defined(NDEBUG) || defined(GFIELD_DCHECK)
#define GF_DCHECK_IS_ON 1
#define GF_DCHECK(condition, message) GF_CHECK(condition, message)
#else
#define GF_DCHECK_IS_ON 0
#define GF_DCHECK(condition, message) void(sizeof(bool(condition)))
#endif
