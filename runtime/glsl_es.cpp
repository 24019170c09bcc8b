#include "runtime/glsl_es.hpp"

#include <regex>

#include "runtime/shader_program.hpp"

namespace gfield {
namespace {

constexpr const char* kVersion = "#version 450";

// What every stage needs before its own text in GLSL ES 3.00.
constexpr const char* kPrelude = R"(#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;
precision highp sampler2DArrayShadow;
precision highp usampler2D;
// bitCount is a GLSL ES 3.10 built-in.
int bitCount(uint v) {
  v = v - ((v >> 1u) & 0x55555555u);
  v = (v & 0x33333333u) + ((v >> 2u) & 0x33333333u);
  return int((((v + (v >> 4u)) & 0x0F0F0F0Fu) * 0x01010101u) >> 24u);
}
)";

}  // namespace

std::string to_glsl_es(const std::string& text, bool vertex) {
  if (text.compare(0, std::char_traits<char>::length(kVersion), kVersion) != 0)
    return {};
  const size_t line_end = text.find('\n');
  std::string body = line_end == std::string::npos ? std::string() : text.substr(line_end + 1);
  static const std::regex binding(R"(layout\s*\(\s*binding\s*=\s*\w+\s*\)\s*)");
  body = std::regex_replace(body, binding, "");
  static const std::regex vertex_out(R"(layout\s*\(\s*location\s*=\s*\d+\s*\)\s*(out\s))");
  static const std::regex fragment_in(R"(layout\s*\(\s*location\s*=\s*\d+\s*\)\s*(in\s))");
  body = std::regex_replace(body, vertex ? vertex_out : fragment_in, "$1");
  return kPrelude + body;
}

bool glsl_es_source(const std::filesystem::path& dir, const std::string& name, std::string& text,
                    std::string& error) {
  ShaderSource source;
  if (!load_shader_source(dir, name, "", source, error))
    return false;
  const bool vertex = std::filesystem::path(name).extension() == ".vert";
  text = to_glsl_es(source.text, vertex);
  if (text.empty()) {
    error = (dir / name).string() + ": does not start with '" + kVersion + "'";
    return false;
  }
  return true;
}

}  // namespace gfield
