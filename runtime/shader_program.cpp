#include "runtime/shader_program.hpp"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "gfield/check.hpp"

namespace gfield {
namespace fs = std::filesystem;

fs::path default_shader_dir() {
  if (const char* env = std::getenv("GFIELD_SHADER_DIR"); env != nullptr && env[0] != '\0')
    return env;
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed =
        (executable.parent_path() / GFIELD_SHADER_DIR_FROM_BINARY).lexically_normal();
    if (fs::is_directory(installed, ec))
      return installed;
  }
  return GFIELD_SOURCE_SHADER_DIR;
}

namespace {

bool read_text(const fs::path& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  text = buffer.str();
  return true;
}

/// Appends `path` (already read into `text`) to `out` with includes expanded.
bool expand(const fs::path& dir, const fs::path& path, const std::string& text,
            const std::string& defines, ShaderSource& out, std::set<fs::path>& seen,
            std::string& error) {
  const int index = int(out.files.size());
  out.files.push_back(path);
  static const std::regex include_line(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    std::smatch match;
    if (index == 0 && number == 1 && line.rfind("#version", 0) == 0) {
      out.text += line + "\n" + defines;
      if (!defines.empty() && defines.back() != '\n')
        out.text += "\n";
      out.text += "#line 2 0\n";
      continue;
    }
    if (!std::regex_match(line, match, include_line)) {
      out.text += line + "\n";
      continue;
    }
    const fs::path included = (dir / match[1].str()).lexically_normal();
    if (seen.insert(included).second) {
      std::string included_text;
      if (!read_text(included, included_text)) {
        error = path.string() + ":" + std::to_string(number) + ": cannot read include \"" +
                match[1].str() + "\" (" + included.string() + ")";
        return false;
      }
      out.text += "#line 1 " + std::to_string(out.files.size()) + "\n";
      if (!expand(dir, included, included_text, defines, out, seen, error))
        return false;
    }
    out.text += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
  }
  return true;
}

GLenum stage_type(const std::string& name) {
  const std::string extension = fs::path(name).extension().string();
  if (extension == ".vert")
    return GL_VERTEX_SHADER;
  if (extension == ".frag")
    return GL_FRAGMENT_SHADER;
  if (extension == ".comp")
    return GL_COMPUTE_SHADER;
  return 0;
}

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

std::string program_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(std::max(length, 1)), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

}  // namespace

bool load_shader_source(const fs::path& dir, const std::string& name, const std::string& defines,
                        ShaderSource& source, std::string& error) {
  source = {};
  const fs::path path = (dir / name).lexically_normal();
  std::string text;
  if (!read_text(path, text)) {
    error = path.string() + ": cannot read the shader file";
    return false;
  }
  if (text.rfind("#version", 0) != 0) {
    error = path.string() + ":1: a shader must start with its #version line";
    return false;
  }
  std::set<fs::path> seen{path};
  return expand(dir, path, text, defines, source, seen, error);
}

std::string translate_shader_log(const std::string& log, const std::vector<fs::path>& files) {
  // Mesa: "0:12(5): error: ...", NVIDIA: "0(12) : error C1008: ...".
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*)");
  static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*)");
  std::istringstream lines(log);
  std::string line, out;
  while (std::getline(lines, line)) {
    std::smatch match;
    std::string prefix;
    if (std::regex_search(line, match, mesa) || std::regex_search(line, match, nvidia)) {
      const size_t file = size_t(std::stoul(match[1].str()));
      const std::string name = file < files.size() ? files[file].string() : match[1].str();
      out += name + ":" + match[2].str() + ": " + match.suffix().str() + "\n";
    } else if (!line.empty()) {
      out += line + "\n";
    }
  }
  return out;
}

ShaderProgram::~ShaderProgram() {
  if (program_ != 0)
    glDeleteProgram(program_);
}

bool ShaderProgram::build(const fs::path& dir, const std::vector<std::string>& stages,
                          const std::string& defines, std::string& error) {
  dir_ = dir;
  stages_ = stages;
  defines_ = defines;
  return rebuild(error);
}

bool ShaderProgram::rebuild(std::string& error) {
  std::vector<std::pair<fs::path, fs::file_time_type>> watched;
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint shader : shaders)
      glDeleteShader(shader);
  };
  std::string messages;
  std::vector<std::string> texts;
  for (const std::string& stage : stages_) {
    const GLenum type = stage_type(stage);
    if (type == 0) {
      error = stage + ": unknown shader stage (expected .vert, .frag or .comp)";
      cleanup();
      return false;
    }
    ShaderSource source;
    if (!load_shader_source(dir_, stage, defines_, source, error)) {
      cleanup();
      return false;
    }
    for (const fs::path& file : source.files) {
      std::error_code ignored;
      watched.emplace_back(file, fs::last_write_time(file, ignored));
    }
    const GLuint shader = glCreateShader(type);
    shaders.push_back(shader);
    texts.push_back(source.text);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE)
      messages += translate_shader_log(shader_log(shader), source.files);
  }
  watched_ = std::move(watched);
  if (!messages.empty()) {
    error = "shader compilation failed:\n" + messages;
    cleanup();
    return false;
  }
  const GLuint program = glCreateProgram();
  for (GLuint shader : shaders)
    glAttachShader(program, shader);
  glLinkProgram(program);
  cleanup();
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  std::string names;
  for (const std::string& stage : stages_)
    names += (names.empty() ? "" : " + ") + stage;
  if (ok != GL_TRUE) {
    error = (dir_ / names).string() + ": link failed:\n" + program_log(program);
    glDeleteProgram(program);
    return false;
  }
  if (program_ != 0)
    glDeleteProgram(program_);
  program_ = program;
  uniforms_ = uniform_table(program, (dir_ / names).string(), texts);
  return true;
}

GLint ShaderProgram::uniform(const char* name) const {
  const auto found = uniforms_.locations.find(name);
  GF_CHECK(found != uniforms_.locations.end(),
           "the shader program " + uniforms_.program + " has no uniform \"" + name + "\"");
  return found->second;
}

GLint ShaderProgram::uniform_if_declared(const char* name) const {
  const auto found = uniforms_.locations.find(name);
  return found == uniforms_.locations.end() ? -1 : found->second;
}

bool ShaderProgram::reload_if_changed(std::string& error) {
  bool changed = false;
  for (const auto& [file, time] : watched_) {
    std::error_code ignored;
    if (fs::last_write_time(file, ignored) != time)
      changed = true;
  }
  if (!changed)
    return false;
  return rebuild(error);
}

}  // namespace gfield
