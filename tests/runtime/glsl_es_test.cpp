// The web player's shaders (runtime/glsl_es.hpp): every stage it runs, turned into GLSL ES 3.00,
// compiles as GLSL ES 3.00 with Khronos' reference compiler, with each set of defines the player
// uses; and the mechanical step does what it says.

#include "runtime/glsl_es.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "runtime/shader_program.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

// The player's defines go after the first line, as docs/web.md says.
std::string with_defines(const std::string& text, const std::string& defines) {
  const size_t first = text.find('\n') + 1;
  return text.substr(0, first) + defines + text.substr(first);
}

// glslangValidator's exit status for `text` as stage `name` (its extension names the stage).
int validate(const std::string& text, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("gfield-glsl-es-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream(file) << text;
  const std::string command =
      "glslangValidator " + file.string() + " > " + (dir / "log").string() + " 2>&1";
  const int status = std::system(command.c_str());
  if (status != 0) {
    std::ifstream log(dir / "log");
    std::string line;
    while (std::getline(log, line))
      ADD_FAILURE() << name << ": " << line;
  }
  fs::remove_all(dir);
  return status;
}

TEST(GlslEs, EveryWebStageCompilesAsGlslEs300) {
  const struct {
    const char* stage;
    const char* defines;
  } cases[] = {
      {"fullscreen.vert", ""},
      {"gbuffer.vert", ""},
      {"gbuffer.frag", ""},
      {"present.frag", ""},
      {"field_trace.frag",
       "#define GF_TRACE_MODE 2\n#define GF_FIELD_MESHES 1\n#define GF_BVH_MESHES 0\n"},
      {"field_trace.frag",
       "#define GF_TRACE_MODE 0\n#define GF_FIELD_MESHES 1\n#define GF_BVH_MESHES 1\n"},
  };
  for (const auto& c : cases) {
    std::string text, error;
    ASSERT_TRUE(glsl_es_source(default_shader_dir(), c.stage, text, error)) << error;
    EXPECT_EQ(text.rfind("#version 300 es\n", 0), 0u) << c.stage;
    EXPECT_EQ(validate(with_defines(text, c.defines), c.stage), 0) << c.stage << "\n" << c.defines;
  }
}

TEST(GlslEs, BindingsAndTheLocationsEsLacksGo) {
  const std::string in =
      "#version 450\nlayout(binding = UNIT_FRAME) uniform sampler2D u_frame;\n"
      "layout(location = 0) in vec3 a_position;\n"
      "layout(location = 1) out vec3 v_normal;\n";
  const std::string vertex = to_glsl_es(in, true);
  EXPECT_EQ(vertex.find("binding"), std::string::npos);
  EXPECT_NE(vertex.find("layout(location = 0) in vec3 a_position;"), std::string::npos);
  EXPECT_NE(vertex.find("\nout vec3 v_normal;"), std::string::npos);
  const std::string fragment = to_glsl_es(in, false);
  EXPECT_NE(fragment.find("\nin vec3 a_position;"), std::string::npos);
  EXPECT_NE(fragment.find("layout(location = 1) out vec3 v_normal;"), std::string::npos);
  EXPECT_EQ(to_glsl_es("#version 330\nvoid main() {}\n", false), "");
}

TEST(GlslEs, AStageThatIsNotGlsl450IsRefusedByName) {
  const fs::path dir =
      fs::temp_directory_path() / ("gfield-glsl-es-bad-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "old.frag") << "#version 330\nvoid main() {}\n";
  std::string text, error;
  EXPECT_FALSE(glsl_es_source(dir, "old.frag", text, error));
  EXPECT_NE(error.find("old.frag: does not start with '#version 450'"), std::string::npos) << error;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gfield
