#include "runtime/uniform_table.hpp"

#include <algorithm>
#include <regex>

namespace gfield {

std::vector<std::string> declared_uniforms(const std::string& source) {
  // "uniform TYPE NAME[SIZE], NAME;" with qualifiers before TYPE; a block has "{" before ";".
  static const std::regex declaration(R"(\buniform\s([^;{]*);)");
  static const std::regex array_size(R"(\[[^\]]*\])");
  static const std::regex last_word(R"((\w+)\s*$)");
  std::vector<std::string> names;
  for (std::sregex_iterator m(source.begin(), source.end(), declaration), end; m != end; ++m) {
    const std::string body = std::regex_replace((*m)[1].str(), array_size, "");
    size_t start = 0;
    while (start <= body.size()) {
      const size_t comma = std::min(body.find(',', start), body.size());
      const std::string part = body.substr(start, comma - start);
      std::smatch word;
      if (std::regex_search(part, word, last_word))
        names.push_back(word[1].str());
      start = comma + 1;
    }
  }
  return names;
}

UniformTable uniform_table(GLuint program, const std::string& name,
                           const std::vector<std::string>& sources) {
  UniformTable table;
  table.program = name;
  for (const std::string& source : sources) {
    for (const std::string& declared : declared_uniforms(source))
      table.locations.emplace(declared, -1);
  }
  GLint count = 0;
  glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  GLint longest = 0;
  glGetProgramInterfaceiv(program, GL_UNIFORM, GL_MAX_NAME_LENGTH, &longest);
  std::string buffer(size_t(std::max(longest, 1)), '\0');
  for (GLint i = 0; i < count; ++i) {
    GLsizei length = 0;
    glGetProgramResourceName(program, GL_UNIFORM, GLuint(i), GLsizei(buffer.size()), &length,
                             buffer.data());
    const std::string active(buffer.data(), size_t(length));
    const GLint location = glGetProgramResourceLocation(program, GL_UNIFORM, active.c_str());
    table.locations[active] = location;
    if (active.size() > 3 && active.compare(active.size() - 3, 3, "[0]") == 0)
      table.locations[active.substr(0, active.size() - 3)] = location;
  }
  return table;
}

}  // namespace gfield
