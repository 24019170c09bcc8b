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
// GF_CHECK_EQ(a, b, message), GF_CHECK_NE, GF_CHECK_LT, GF_CHECK_LE, GF_CHECK_GT, GF_CHECK_GE:
// GF_CHECK of a comparison that prints both values: "FILE:LINE: check failed: A == B (3 vs 4):
// MESSAGE". Each operand is evaluated once.
//
// `message` is anything a std::string_view is made from; it is evaluated only on failure.

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>

namespace gfield::detail {

[[noreturn]] inline void check_failed(const char* file, int line, const char* condition,
                                      std::string_view message) {
  std::fprintf(stderr, "%s:%d: check failed: %s: %.*s\n", file, line, condition,
               int(message.size()), message.data());
  std::fflush(stderr);
  std::abort();
}

/// A failed comparison: its expression and both values, then the message.
template <class A, class B>
[[noreturn]] void check_op_failed(const char* file, int line, const char* expression, const A& a,
                                  const B& b, std::string_view message) {
  std::ostringstream values;
  values.precision(17);
  values << expression << " (" << a << " vs " << b << ")";
  check_failed(file, line, values.str().c_str(), message);
}

}  // namespace gfield::detail

#define GF_CHECK(condition, message)                                            \
  ((condition) ? void(0)                                                        \
               : ::gfield::detail::check_failed(__FILE__, __LINE__, #condition, \
                                                std::string_view(message)))

#define GF_CHECK_OP(op, a, b, message)                                                     \
  do {                                                                                     \
    const auto& gf_check_a = (a);                                                          \
    const auto& gf_check_b = (b);                                                          \
    if (!(gf_check_a op gf_check_b))                                                       \
      ::gfield::detail::check_op_failed(__FILE__, __LINE__, #a " " #op " " #b, gf_check_a, \
                                        gf_check_b, std::string_view(message));            \
  } while (false)
#define GF_CHECK_EQ(a, b, message) GF_CHECK_OP(==, a, b, message)
#define GF_CHECK_NE(a, b, message) GF_CHECK_OP(!=, a, b, message)
#define GF_CHECK_LT(a, b, message) GF_CHECK_OP(<, a, b, message)
#define GF_CHECK_LE(a, b, message) GF_CHECK_OP(<=, a, b, message)
#define GF_CHECK_GT(a, b, message) GF_CHECK_OP(>, a, b, message)
#define GF_CHECK_GE(a, b, message) GF_CHECK_OP(>=, a, b, message)

#if !defined(NDEBUG) || defined(GFIELD_DCHECK)
#define GF_DCHECK_IS_ON 1
#define GF_DCHECK(condition, message) GF_CHECK(condition, message)
#else
#define GF_DCHECK_IS_ON 0
#define GF_DCHECK(condition, message) void(sizeof(bool(condition)))
#endif
