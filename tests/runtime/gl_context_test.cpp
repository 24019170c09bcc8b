// Headless OpenGL on whatever EGL offers (llvmpipe in CI): context, shader files with includes,
// error messages with FILE:LINE, and a real render read back from an FBO.

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "runtime/framebuffer.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/shader_program.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/gl_suite.hpp"

namespace gfield {
namespace {
namespace fs = std::filesystem;

void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

class GlTest : public test::GlSuite {
 protected:
  fs::path dir_ = fs::path(gfield::build_paths::test_tmp()) / "gl_context_test";
};

TEST_F(GlTest, ContextIsOpenGl45Core) {
  ASSERT_NE(context_, nullptr);
  EXPECT_FALSE(context_->renderer().empty());
  EXPECT_GE(epoxy_gl_version(), 45);
  EXPECT_NE(context_->platform().find("EGL"), std::string::npos);
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  EXPECT_GE(max_size, 3456) << "a 24-sample field needs a 3456^2 2D texture";
}

TEST_F(GlTest, IncludesAreResolvedOnceWithLineDirectives) {
  write_file(dir_ / "lib/a.glsl", "#include \"lib/b.glsl\"\nfloat a() { return b(); }\n");
  write_file(dir_ / "lib/b.glsl", "float b() { return 1.0; }\n");
  write_file(dir_ / "s.frag",
             "#version 450\n#include \"lib/a.glsl\"\n#include \"lib/b.glsl\"\nvoid main() {}\n");
  ShaderSource source;
  std::string error;
  ASSERT_TRUE(load_shader_source(dir_, "s.frag", "#define X 1\n", source, error)) << error;
  ASSERT_EQ(source.files.size(), 3u);
  EXPECT_EQ(source.files[1].filename(), "a.glsl");
  EXPECT_EQ(source.files[2].filename(), "b.glsl");
  EXPECT_EQ(source.text.rfind("#version 450\n#define X 1\n#line 2 0\n", 0), 0u);
  // b.glsl is pasted once, inside a.glsl.
  size_t first = source.text.find("float b()");
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(source.text.find("float b()", first + 1), std::string::npos);

  write_file(dir_ / "bad.frag", "#version 450\n#include \"lib/missing.glsl\"\n");
  EXPECT_FALSE(load_shader_source(dir_, "bad.frag", "", source, error));
  EXPECT_NE(error.find("bad.frag:2"), std::string::npos) << error;
}

TEST_F(GlTest, CompileErrorsNameFileAndLine) {
  write_file(dir_ / "lib/broken.glsl",
             "float ok() { return 1.0; }\nfloat broken() { return x; }\n");
  write_file(dir_ / "e.frag",
             "#version 450\n#include \"lib/broken.glsl\"\nout vec4 c;\nvoid main() { c = "
             "vec4(ok()); }\n");
  write_file(dir_ / "e.vert", "#version 450\nvoid main() { gl_Position = vec4(0); }\n");
  ShaderProgram program;
  std::string error;
  ASSERT_FALSE(program.build(dir_, {"e.vert", "e.frag"}, "", error));
  EXPECT_NE(error.find("broken.glsl:2:"), std::string::npos) << error;
}

TEST_F(GlTest, RendersIntoFramebufferAndReadsBack) {
  // A quad covering the left half of the picture, coloured by a uniform; the right half is
  // the clear colour.
  write_file(
      dir_ / "t.vert",
      "#version 450\nconst vec2 p[4] = vec2[](vec2(-1,-1), vec2(0,-1), vec2(-1,1), vec2(0,1));\n"
      "void main() { gl_Position = vec4(p[gl_VertexID], 0.5, 1); }\n");
  write_file(dir_ / "lib/color.glsl",
             "uniform vec3 u_color;\nvec4 color() { return vec4(u_color, 1); }\n");
  write_file(dir_ / "t.frag",
             "#version 450\n#include \"lib/color.glsl\"\nlayout(location = 0) out vec4 o;\n"
             "void main() { o = color() * (gl_FragCoord.y < 8.0 ? 0.5 : 1.0); }\n");
  ShaderProgram program;
  std::string error;
  ASSERT_TRUE(program.build(dir_, {"t.vert", "t.frag"}, "", error)) << error;
  Framebuffer target;
  ASSERT_TRUE(target.resize(64, 32));
  target.bind();
  glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glUseProgram(program.id());
  glUniform3f(program.uniform("u_color"), 0.25f, 0.5f, 0.75f);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  const RgbaImage image = target.read();
  glDeleteVertexArrays(1, &vao);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 32);
  const auto at = [&](int x, int y) { return image.pixels[size_t(y) * 64 + size_t(x)]; };
  EXPECT_FLOAT_EQ(at(5, 5).y, 0.5f);    // top rows: full colour
  EXPECT_FLOAT_EQ(at(5, 30).y, 0.25f);  // bottom 8 rows (GL y < 8): half colour, read flipped
  EXPECT_FLOAT_EQ(at(50, 5).x, 0.1f);   // right half: clear colour
  EXPECT_FLOAT_EQ(at(50, 5).z, 0.3f);
  int covered = 0;
  for (const glm::vec4& p : image.pixels)
    covered += p.z > 0.5f ? 1 : 0;
  EXPECT_EQ(covered, 32 * 24);  // the left half, 8 bottom rows excepted (z = 0.375 there)
}

// Uniform locations come from the table made at link time: a dropped (unused) uniform is -1 as
// GL's own look-up, and a name the program does not declare stops it, naming both.
TEST_F(GlTest, UniformsAreLookedUpAtLinkAndAMisspeltOneStopsTheProgram) {
  write_file(dir_ / "u.vert",
             "#version 450\nuniform vec2 u_offsets[2];\nuniform float u_unused;\n"
             "void main() { gl_Position = vec4(u_offsets[gl_VertexID % 2], 0.5, 1); }\n");
  write_file(dir_ / "u.frag",
             "#version 450\nlayout(location = 0) uniform vec3 u_color;\n"
             "layout(location = 0) out vec4 o;\nvoid main() { o = vec4(u_color, 1); }\n");
  ShaderProgram program;
  std::string error;
  ASSERT_TRUE(program.build(dir_, {"u.vert", "u.frag"}, "", error)) << error;
  EXPECT_EQ(program.uniform("u_color"), 0);
  EXPECT_EQ(program.uniform("u_offsets"), glGetUniformLocation(program.id(), "u_offsets"));
  EXPECT_GE(program.uniform("u_offsets"), 0);
  EXPECT_EQ(program.uniform("u_offsets[0]"), program.uniform("u_offsets"));
  EXPECT_EQ(program.uniform("u_unused"), -1);
  EXPECT_EQ(program.uniform_if_declared("u_colour"), -1);
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(program.uniform("u_colour"), "u.vert \\+ u.frag has no uniform \"u_colour\"");
}

}  // namespace
}  // namespace gfield
