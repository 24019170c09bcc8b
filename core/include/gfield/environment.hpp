#pragma once
// The distant environment: radiance arriving from a direction. Four kinds: the built-in
// procedural "studio", a constant colour, an equirectangular image (EXR/HDR/PNG) or six cube
// faces. The direction mappings and the studio are written once in shaders/lib/environment.glsl
// and shared with the GPU runtime.

#include <array>
#include <string>

#include <glm/glm.hpp>

#include "gfield/gpu_contract.hpp"
#include "gfield/image.hpp"

namespace gfield {

/// Environment kinds; the numbers are the shaders' ENV_* codes (shaders/lib/contract.glsl).
enum class EnvironmentType {
  kStudio = gpu::ENV_STUDIO,
  kConstant = gpu::ENV_CONSTANT,
  kEquirect = gpu::ENV_EQUIRECT,
  kCube = gpu::ENV_CUBE,
};

/// What a scene file says about the environment (paths already resolved against the scene file).
struct EnvironmentDesc {
  EnvironmentType type = EnvironmentType::kStudio;
  glm::vec3 color{1.0f};   ///< kConstant: the radiance
  float intensity = 1.0f;  ///< every kind is multiplied by this
  std::string file;        ///< kEquirect: the image
  /// kCube: the faces in OpenGL order +X, -X, +Y, -Y, +Z, -Z; square, all of one size.
  std::array<std::string, 6> faces;
};

/// An environment ready for lookups (images loaded).
struct Environment {
  EnvironmentDesc desc;
  Image equirect;
  std::array<Image, 6> faces;
};

/// Loads the images of `desc`. False with "FILE: problem" (missing file, unequal or non-square
/// cube faces).
bool load_environment(const EnvironmentDesc& desc, Environment& environment, std::string& error);

/// Radiance from unit direction `direction` (bilinear filtering for images).
glm::vec3 environment_radiance(const Environment& environment, glm::vec3 direction);

/// The procedural studio alone (shaders/lib/environment.glsl), unit direction.
glm::vec3 studio_environment_radiance(glm::vec3 direction);
/// Equirectangular coordinates (u, v) in [0,1]^2 of a unit direction (v = 0 up).
glm::vec2 equirect_uv(glm::vec3 direction);
/// Cube-map coordinates (s, t, face) of a direction, OpenGL's rule, face 0..5 = +X..-Z.
glm::vec3 cube_coords(glm::vec3 direction);

}  // namespace gfield
