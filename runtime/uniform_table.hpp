#pragma once
// The uniforms of a linked GL program by name, found once when it links (ShaderProgram): the
// active ones with their locations, and those its stages declare that the compiler dropped
// (unused: location -1, which GL's glUniform* ignore). A name in neither is a mistake in the
// caller (a typo, or a uniform the shader no longer has).

#include <string>
#include <unordered_map>
#include <vector>

#include <epoxy/gl.h>

namespace gfield {

struct UniformTable {
  std::string program;  ///< the program's stage files, for messages ("a.vert + b.frag")
  /// Uniform name -> location (-1: declared, dropped). Arrays under their name and name[0].
  std::unordered_map<std::string, GLint> locations;
};

/// The table of linked `program` named `name`, whose stages' sources (includes expanded) are
/// `sources`.
UniformTable uniform_table(GLuint program, const std::string& name,
                           const std::vector<std::string>& sources);

/// The names a GLSL source declares as plain uniforms (not blocks), in order; arrays without
/// their size.
std::vector<std::string> declared_uniforms(const std::string& source);

}  // namespace gfield
