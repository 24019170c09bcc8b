#pragma once
// GLSL's vocabulary in C++: the types and built-in functions that the files of shaders/lib
// compiled by both languages may use, as GLM provides them, gathered in namespace gfield::glsl
// (docs/architecture.md, "The CPU/GPU dialect"). A C++ file that includes such a file includes
// gfield/glsl_begin.hpp before it and gfield/glsl_end.hpp after it, inside a scope that sees
// these names (`using namespace gfield::glsl;` in a source file; using-declarations of the names
// it needs in a header).

#include <glm/glm.hpp>
#include <glm/gtc/integer.hpp>
#include <glm/integer.hpp>

namespace gfield::glsl {

using glm::bvec2;
using glm::bvec3;
using glm::dmat3;
using glm::dmat4;
using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using glm::ivec2;
using glm::ivec3;
using glm::ivec4;
using glm::mat3;
using glm::mat4;
using glm::uvec2;
using glm::uvec3;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using uint = unsigned int;

using glm::abs;
using glm::acos;
using glm::asin;
using glm::atan;
using glm::bitCount;
using glm::ceil;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::distance;
using glm::dot;
using glm::exp;
using glm::floatBitsToInt;
using glm::floatBitsToUint;
using glm::floor;
using glm::fract;
using glm::intBitsToFloat;
using glm::inversesqrt;
using glm::length;
using glm::log;
using glm::max;
using glm::min;
using glm::mix;
using glm::mod;
using glm::normalize;
using glm::pow;
using glm::reflect;
using glm::refract;
using glm::round;
using glm::sign;
using glm::sin;
using glm::smoothstep;
using glm::sqrt;
using glm::step;
using glm::tan;
using glm::transpose;
using glm::uintBitsToFloat;

}  // namespace gfield::glsl
