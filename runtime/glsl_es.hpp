#pragma once
// The web player's shaders (docs/web.md, "Shaders"): a stage of shaders/ turned into GLSL ES 3.00
// for WebGL2, from the same files as the runtime's GLSL 4.50. The step is mechanical and the
// files hold the one difference that is not (`#ifdef GL_ES`: storage buffers become uniform
// blocks and textures behind the same fetch functions):
//   - includes resolved as for the runtime (shader_program.hpp, load_shader_source);
//   - `#version 450` becomes `#version 300 es` and the prelude: highp precision for floats, ints
//     and every sampler type the files use, and bitCount (a GLSL ES 3.10 built-in);
//   - `layout(binding = ...)` qualifiers go (GLSL ES 3.00 has none: the player binds units by
//     uniform name); a vertex stage's outputs and a fragment stage's inputs lose their
//     `layout(location = ...)` (ES 3.00 matches them by name).
// A program's defines go after the first line, as the runtime puts them after #version.

#include <filesystem>
#include <string>

namespace gfield {

/// The GLSL ES 3.00 text of stage `name` (e.g. "field_trace.frag") of the shader folder `dir`.
/// False with "FILE:LINE: problem" for a missing file or a bad include, or "FILE: problem" for a
/// stage that does not start with `#version 450`.
bool glsl_es_source(const std::filesystem::path& dir, const std::string& name, std::string& text,
                    std::string& error);

/// The GLSL ES 3.00 form of `text`, a resolved GLSL 4.50 stage; `vertex` for a vertex stage (its
/// outputs lose their locations), else a fragment stage (its inputs do). Empty when `text` does
/// not start with `#version 450`.
std::string to_glsl_es(const std::string& text, bool vertex);

}  // namespace gfield
