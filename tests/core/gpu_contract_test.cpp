// shaders/lib/contract.glsl compiled as C++ (gfield/gpu_contract.hpp): its codes are the enums'
// and its camera ray is gfield::camera_ray's.

#include "gfield/gpu_contract.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "gfield/scene.hpp"

namespace gfield {
namespace {

TEST(GpuContract, CodesAreTheEnumsValues) {
  EXPECT_EQ(int(ShapeType::kHollowCylinder), gpu::SHAPE_HOLLOW_CYLINDER);
  EXPECT_EQ(int(MaterialType::kDielectric), gpu::MATERIAL_DIELECTRIC);
  EXPECT_EQ(int(TextureType::kColorChart), gpu::TEXTURE_COLOR_CHART);
  EXPECT_EQ(int(EnvironmentType::kCube), gpu::ENV_CUBE);
  // Every texture unit is distinct (one table for every pass).
  const int units[] = {gpu::UNIT_GI_POSITIONS,
                       gpu::UNIT_GI_NORMALS,
                       gpu::UNIT_FIELDS,
                       gpu::UNIT_PROBE_ORIGINS,
                       gpu::UNIT_PROBE_DIRECTIONS,
                       gpu::UNIT_ENVIRONMENT,
                       gpu::UNIT_GBUFFER_POSITION,
                       gpu::UNIT_GBUFFER_NORMAL,
                       gpu::UNIT_GBUFFER_GEOMETRIC,
                       gpu::UNIT_THICKNESS,
                       gpu::UNIT_CUBE,
                       gpu::UNIT_BACK,
                       gpu::UNIT_FRONT,
                       gpu::UNIT_NEARBY,
                       gpu::UNIT_PEEL_PREVIOUS,
                       gpu::UNIT_PEEL_LAYERS,
                       gpu::UNIT_PEEL_LAYERS + 3,
                       gpu::UNIT_CLASS_IMAGES,
                       gpu::UNIT_SHADOW_MAPS,
                       gpu::UNIT_FRAME};
  for (size_t a = 0; a < std::size(units); ++a)
    for (size_t b = a + 1; b < std::size(units); ++b)
      EXPECT_NE(units[a], units[b]) << a << " " << b;
}

TEST(GpuContract, CameraDirectionIsCameraRays) {
  Camera camera;
  camera.position = {0.3f, 1.2f, 3.0f};
  camera.target = {-0.2f, 0.1f, 0.4f};
  camera.fov_degrees = 47.0f;
  const int width = 320, height = 200;
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_half = std::tan(glm::radians(camera.fov_degrees) * 0.5f);
  const glm::vec2 tan_halves(tan_half * float(width) / float(height), tan_half);
  for (const glm::vec2 pixel : {glm::vec2(0.5f, 0.5f), glm::vec2(160.0f, 100.0f),
                                glm::vec2(319.5f, 12.25f), glm::vec2(7.75f, 199.5f)}) {
    const glm::vec3 gpu_direction =
        gpu::gf_camera_direction(forward, right, up, tan_halves, glm::vec2(width, height), pixel);
    const CameraRay cpu = camera_ray(camera, width, height, glm::dvec2(pixel));
    EXPECT_LT(glm::distance(gpu_direction, glm::vec3(cpu.direction)), 1e-6f);
  }
}

}  // namespace
}  // namespace gfield
