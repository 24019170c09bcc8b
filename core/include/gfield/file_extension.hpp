#pragma once
// A file name's extension as the readers compare it.

#include <string>

namespace gfield {

/// The extension of `path`'s file name with its dot, in lower case ASCII ("a/Mesh.OBJ" -> ".obj",
/// "a.b/c" -> "", ".obj" -> "").
std::string lower_extension(const std::string& path);

}  // namespace gfield
