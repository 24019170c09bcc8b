#pragma once
// GLSL programs built from files in shaders/: `#include "lib/x.glsl"` lines are resolved
// against the shader folder (recursively, each file once), `#line` directives keep the
// compiler's line numbers, and compile/link logs are rewritten to FILE:LINE. Programs can be
// rebuilt at run time when their files change (a failed rebuild keeps the old program). Uniform
// locations are looked up once, when a program links (runtime/uniform_table.hpp).

#include <filesystem>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "runtime/uniform_table.hpp"

namespace gfield {

/// The folder holding the shaders: $GFIELD_SHADER_DIR if set; else, for an installed
/// executable, share/gfield/shaders beside its bin/ folder (found through /proc/self/exe); else
/// the source tree's shaders/ (an executable run from the build folder).
std::filesystem::path default_shader_dir();

/// One shader stage's source after include resolution. `files[k]` is the path of source-string
/// number k in the `#line` directives (files[0] is the stage's own file).
struct ShaderSource {
  std::string text;
  std::vector<std::filesystem::path> files;
};

/// Reads `dir/name`, inserts `defines` (lines such as "#define X 1") after its #version line and
/// resolves includes. False with "FILE:LINE: problem" for a missing file or a bad include.
bool load_shader_source(const std::filesystem::path& dir, const std::string& name,
                        const std::string& defines, ShaderSource& source, std::string& error);

/// Rewrites the "N:LINE(COL)" (Mesa) and "N(LINE)" (NVIDIA) prefixes of a GL info log into
/// "FILE:LINE".
std::string translate_shader_log(const std::string& log,
                                 const std::vector<std::filesystem::path>& files);

/// A linked program of a vertex and a fragment stage (or a single compute stage).
class ShaderProgram {
 public:
  ShaderProgram() = default;
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  /// Builds from `dir`: stage files (e.g. {"mesh.vert", "field_trace.frag"}), stage types
  /// deduced from the extension (.vert, .frag, .comp). On failure the error lists every
  /// compile/link message as FILE:LINE: message, and the previous program stays.
  bool build(const std::filesystem::path& dir, const std::vector<std::string>& stages,
             const std::string& defines, std::string& error);
  /// Rebuilds when a file of the program (includes too) changed on disk since the last build.
  /// Returns true when it rebuilt successfully; `error` is set when it tried and failed.
  bool reload_if_changed(std::string& error);
  /// Rebuilds unconditionally with the same files and defines.
  bool rebuild(std::string& error);

  GLuint id() const { return program_; }
  /// The location of uniform `name`: -1 for one a stage declares but the compiler dropped. A
  /// name no stage declares (a typo) stops the program with a message naming the program's
  /// stages and the uniform.
  GLint uniform(const char* name) const;
  /// As uniform(), but -1 for a name no stage declares: for the setters that serve every program
  /// (GpuScene::set_uniforms, set_camera_uniforms, ...), each setting the uniforms it has.
  GLint uniform_if_declared(const char* name) const;

 private:
  std::filesystem::path dir_;
  std::vector<std::string> stages_;
  std::string defines_;
  std::vector<std::pair<std::filesystem::path, std::filesystem::file_time_type>> watched_;
  GLuint program_ = 0;
  UniformTable uniforms_;
};

}  // namespace gfield
