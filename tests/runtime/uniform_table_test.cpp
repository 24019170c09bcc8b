// The uniforms a GLSL source declares (runtime/uniform_table.hpp), which the link-time table
// keeps at -1 when the compiler drops them.

#include "runtime/uniform_table.hpp"

#include <gtest/gtest.h>

namespace gfield {
namespace {

TEST(UniformTable, DeclaredUniformsAreEveryPlainUniformButNoBlock) {
  const std::string source =
      "#version 450\n"
      "uniform mat4 u_view_projection;\n"
      "layout(binding = 3) uniform sampler2DArray u_images;  // a comment\n"
      "uniform highp float u_a, u_b[4];\n"
      "layout(binding = 15) uniform sampler2D u_layers[GLASS_LAYERS];\n"
      "layout(std140) uniform Block { vec4 member; };\n"
      "uniform int u_last ;\n"
      "float uniformity;\n";
  const std::vector<std::string> expected = {"u_view_projection", "u_images", "u_a", "u_b",
                                             "u_layers",          "u_last"};
  EXPECT_EQ(declared_uniforms(source), expected);
  EXPECT_TRUE(declared_uniforms("void main() {}\n").empty());
}

}  // namespace
}  // namespace gfield
