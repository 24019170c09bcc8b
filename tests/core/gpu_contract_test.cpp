// shaders/lib/contract.glsl compiled as C++ (gfield/gpu_contract.hpp): its codes are the enums',
// its texture units one table, and its camera ray is gfield::camera_ray's.

#include "gfield/gpu_contract.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "gfield/scene.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

// Every texture unit of the contract, with the units it spans (an array of samplers spans
// several): written by name so that UnitsAreAllListed can find a unit left out.
struct UnitRange {
  const char* name;
  int first;
  int count;
};
#define GF_UNITS(unit, count) (UnitRange{#unit, gpu::unit, count})
constexpr UnitRange kUnits[] = {
    GF_UNITS(UNIT_GI_POSITIONS, 1),
    GF_UNITS(UNIT_GI_NORMALS, 1),
    GF_UNITS(UNIT_FIELDS, 1),
    GF_UNITS(UNIT_PROBE_ORIGINS, 1),
    GF_UNITS(UNIT_PROBE_DIRECTIONS, 1),
    GF_UNITS(UNIT_ENVIRONMENT, 1),
    GF_UNITS(UNIT_GBUFFER_POSITION, 1),
    GF_UNITS(UNIT_GBUFFER_NORMAL, 1),
    GF_UNITS(UNIT_GBUFFER_GEOMETRIC, 1),
    GF_UNITS(UNIT_THICKNESS, 1),
    GF_UNITS(UNIT_CUBE, 1),
    GF_UNITS(UNIT_BACK, 1),
    GF_UNITS(UNIT_FRONT, 1),
    GF_UNITS(UNIT_NEARBY, 1),
    GF_UNITS(UNIT_PEEL_PREVIOUS, 1),
    GF_UNITS(UNIT_PEEL_LAYERS, gpu::GLASS_LAYERS),
    GF_UNITS(UNIT_CLASS_IMAGES, 1),
    GF_UNITS(UNIT_SHADOW_MAPS, 1),
    GF_UNITS(UNIT_FRAME, 1),
    GF_UNITS(UNIT_GI_ALBEDO, 1),
    GF_UNITS(UNIT_MESH_TEXTURES, 1),
    GF_UNITS(UNIT_GBUFFER_ALBEDO, 1),
    GF_UNITS(UNIT_PROBE_SELF, 1),
};
#undef GF_UNITS

/// Whether the units of kUnits are distinct and in [0, UNIT_COUNT), and fill it (one table for
/// every pass: a unit means one texture).
constexpr bool units_fill_the_table_once() {
  int uses[gpu::UNIT_COUNT] = {};
  int total = 0;
  for (const UnitRange& range : kUnits) {
    for (int unit = range.first; unit < range.first + range.count; ++unit) {
      if (unit < 0 || unit >= gpu::UNIT_COUNT || uses[unit]++ > 0)
        return false;
      ++total;
    }
  }
  return total == gpu::UNIT_COUNT;
}
static_assert(units_fill_the_table_once(),
              "contract.glsl: two texture units are the same, or one is not below UNIT_COUNT, or "
              "UNIT_COUNT is not the number of units");

TEST(GpuContract, CodesAreTheEnumsValues) {
  EXPECT_EQ(int(ShapeType::kHollowCylinder), gpu::SHAPE_HOLLOW_CYLINDER);
  EXPECT_EQ(int(MaterialType::kDielectric), gpu::MATERIAL_DIELECTRIC);
  EXPECT_EQ(int(TextureType::kColorChart), gpu::TEXTURE_COLOR_CHART);
  EXPECT_EQ(int(EnvironmentType::kCube), gpu::ENV_CUBE);
}

// kUnits names every UNIT_ constant of contract.glsl (but UNIT_COUNT), so that the static check
// above covers a unit added there.
TEST(GpuContract, UnitsAreAllListed) {
  std::ifstream in(std::string(gfield::build_paths::tests_dir()) + "/../shaders/lib/contract.glsl");
  ASSERT_TRUE(in);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::regex unit(R"(GF_CONST int (UNIT_\w+) =)");
  std::set<std::string> declared;
  for (std::sregex_iterator m(text.begin(), text.end(), unit), end; m != end; ++m) {
    if ((*m)[1].str() != "UNIT_COUNT")
      declared.insert((*m)[1].str());
  }
  std::set<std::string> listed;
  for (const UnitRange& range : kUnits)
    listed.insert(range.name);
  EXPECT_EQ(declared, listed);
  EXPECT_EQ(listed.size(), std::size(kUnits));
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
