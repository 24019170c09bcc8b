// Environment lookups. The mappings and the studio come from the shared GLSL file.

#include "gfield/environment.hpp"

#include <cmath>

#include "gfield/glsl_names.hpp"
#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace environment_glsl {
using namespace gfield::glsl;
using gpu::GF_PI;
#include "gfield/glsl_begin.hpp"

#include "../../shaders/lib/environment.glsl"

#include "gfield/glsl_end.hpp"
}  // namespace environment_glsl

glm::vec3 studio_environment_radiance(glm::vec3 direction) {
  return environment_glsl::studio_environment(direction);
}

glm::vec2 equirect_uv(glm::vec3 direction) {
  return environment_glsl::env_equirect_uv(direction);
}

glm::vec3 cube_coords(glm::vec3 direction) {
  return environment_glsl::env_cube_coords(direction);
}

bool load_environment(const EnvironmentDesc& desc, Environment& environment, std::string& error) {
  Environment result;
  result.desc = desc;
  if (desc.type == EnvironmentType::kEquirect) {
    if (!load_image(desc.file, result.equirect, error))
      return false;
  } else if (desc.type == EnvironmentType::kCube) {
    for (size_t f = 0; f < 6; ++f) {
      if (!load_image(desc.faces[f], result.faces[f], error))
        return false;
      const Image& face = result.faces[f];
      if (face.width != face.height || face.width != result.faces[0].width) {
        error = desc.faces[f] + ": cube faces must be square and all of one size (face 0 is " +
                std::to_string(result.faces[0].width) + "x" +
                std::to_string(result.faces[0].height) + ", this one " +
                std::to_string(face.width) + "x" + std::to_string(face.height) + ")";
        return false;
      }
    }
  }
  environment = std::move(result);
  return true;
}

glm::vec3 environment_radiance(const Environment& environment, glm::vec3 direction) {
  const EnvironmentDesc& desc = environment.desc;
  glm::vec3 radiance(0.0f);
  switch (desc.type) {
    case EnvironmentType::kStudio:
      radiance = environment_glsl::studio_environment(direction);
      break;
    case EnvironmentType::kConstant:
      radiance = desc.color;
      break;
    case EnvironmentType::kEquirect: {
      const Image& image = environment.equirect;
      const glm::vec2 uv = environment_glsl::env_equirect_uv(direction);
      radiance =
          sample_bilinear(image, uv.x * float(image.width), uv.y * float(image.height), true);
      break;
    }
    case EnvironmentType::kCube: {
      const glm::vec3 c = environment_glsl::env_cube_coords(direction);
      const Image& image = environment.faces[size_t(c.z)];
      radiance = sample_bilinear(image, c.x * float(image.width), c.y * float(image.height), false);
      break;
    }
  }
  return radiance * desc.intensity;
}

}  // namespace gfield
