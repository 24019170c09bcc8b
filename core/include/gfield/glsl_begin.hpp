// Opens the CPU/GPU dialect for C++ (docs/architecture.md, "The CPU/GPU dialect"): include this
// file before including a file of shaders/lib as C++, and gfield/glsl_end.hpp after it, which
// removes every macro defined here, so that nothing of the dialect is visible past the pair.
// Not guarded: each pair opens the dialect again. The including scope must see GLSL's names:
// include gfield/glsl_names.hpp at file scope first, and bring its names into the scope.
//
// GF_CONST: a constant (`const` in GLSL), static constexpr here so that a file included inside a
// struct declares members and one included in a namespace declares constants of each file.
// GF_INLINE: a function of a header (contract.glsl). GF_IN(T), GF_OUT(T), GF_INOUT(T): GLSL's
// parameter qualifiers (in, out, inout) as a const reference and references.

#ifdef GF_CONST
#error "gfield/glsl_begin.hpp: the dialect is open already (a glsl_end.hpp is missing)"
#endif
#define GF_CONST static constexpr
#define GF_INLINE inline
#define GF_IN(T) const T&
#define GF_OUT(T) T&
#define GF_INOUT(T) T&
