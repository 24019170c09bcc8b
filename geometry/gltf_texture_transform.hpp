#pragma once
// KHR_texture_transform on a glTF textureInfo: which TEXCOORD_n set a texture reads and the
// affine map of its texture coordinates (offset, rotation, scale), as the extension defines it:
// uv' = T(offset) * R(rotation) * S(scale) * uv, in glTF's uv space (v down). Internal to the
// glTF code.

#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace gfield {

struct TextureTransform {
  int tex_coord = 0;         ///< the TEXCOORD_n set: the extension's texCoord, else the info's
  glm::dmat3 matrix{1.0};    ///< column-major, applied to (u, v, 1)
  bool transformed = false;  ///< the extension is there
};

/// The transform of textureInfo `info` (a JSON object: index, texCoord, extensions). False with
/// `what` ("KHR_texture_transform.offset: ...") for members of the wrong form or not finite, a
/// scale or offset beyond +-1e4 (kMaxTextureCoordinate), a texCoord outside [0, 255].
bool texture_transform(const nlohmann::json& info, TextureTransform& transform, std::string& what);

/// `uv` (glTF's convention, v down) transformed, as gfield reads it (v up: 1 - v').
glm::dvec2 transformed_uv(const TextureTransform& transform, glm::dvec2 uv);

}  // namespace gfield
