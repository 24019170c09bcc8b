// The CPU/GPU contract (shaders/lib/contract.glsl): every analytic shape with every material it
// takes, drawn by the GPU (the field method: shapes.glsl, the contract's codes, buffer layouts,
// binding slots and camera ray) and by the CPU (the reference tracer: analytic_primitives.cpp,
// camera_ray), at the same sample positions, must give the same picture.

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "gfield/image_metrics.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/methods/geometry_field.hpp"
#include "runtime/shader_program.hpp"
#include "test_support/gl_suite.hpp"

namespace gfield {
namespace {

constexpr int kSize = 64;

/// One shape of `type` with `material` in front of a colour-chart backdrop on a checker floor.
Scene shape_scene(ShapeType type, MaterialType material) {
  Scene scene;
  scene.filename = "contract-test";
  scene.width = scene.height = kSize;
  scene.camera.position = {0.4f, 1.0f, 3.2f};
  scene.camera.target = {0.0f, 0.1f, 0.0f};
  scene.camera.fov_degrees = 40.0f;
  scene.ambient = glm::vec3(0.15f);
  Light light;
  light.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.5f));
  light.intensity = 1.3f;
  scene.lights = {light};
  SceneObject shape;
  shape.shape.type = type;
  shape.shape.radius = 0.5f;
  shape.shape.height = 0.9f;
  shape.shape.size = glm::vec3(0.9f, 0.8f, 0.7f);
  shape.shape.thickness = type == ShapeType::kSlab ? 0.3f : 0.15f;
  shape.transform.rotate_degrees = {15.0f, 30.0f, 0.0f};
  shape.material.type = material;
  shape.material.texture =
      material == MaterialType::kDiffuse ? TextureType::kChecker : TextureType::kNone;
  shape.material.color = glm::vec3(0.85f, 0.8f, 0.7f);
  SceneObject chart;
  chart.shape.type = ShapeType::kQuad;
  chart.shape.size = glm::vec3(3.0f, 2.0f, 0.0f);
  chart.transform.translate = {0.0f, 0.3f, -1.5f};
  chart.material.texture = TextureType::kColorChart;
  SceneObject floor;
  floor.shape.type = ShapeType::kQuad;
  floor.shape.size = glm::vec3(6.0f, 6.0f, 0.0f);
  floor.transform.rotate_degrees = {-90.0f, 0.0f, 0.0f};
  floor.transform.translate = {0.0f, -0.7f, 0.0f};
  floor.material.texture = TextureType::kChecker;
  scene.objects = {shape, chart, floor};
  return scene;
}

class Contract : public test::GlSuite {};

TEST_F(Contract, EveryAnalyticShapeAndMaterialMatchesTheCpu) {
  std::string error;
  for (ShapeType type : {ShapeType::kSphere, ShapeType::kQuad, ShapeType::kBox,
                         ShapeType::kCylinder, ShapeType::kSlab, ShapeType::kHollowCylinder}) {
    for (MaterialType material :
         {MaterialType::kDiffuse, MaterialType::kMirror, MaterialType::kDielectric}) {
      if (material == MaterialType::kDielectric && !shape_is_closed(type))
        continue;
      const Scene scene = shape_scene(type, material);
      const std::string what = std::string(shape_name(type)) + " " +
                               (material == MaterialType::kDiffuse  ? "diffuse"
                                : material == MaterialType::kMirror ? "mirror"
                                                                    : "dielectric");
      SCOPED_TRACE(what);
      ReferenceTracer tracer;
      ASSERT_TRUE(tracer.build(scene, error)) << error;
      RenderOptions options;
      options.width = options.height = kSize;
      options.samples_per_pixel = 1;
      options.max_depth = 4;
      options.jitter = false;
      const Image cpu = clamped_to_display(tracer.render(options));
      GpuScene gpu;
      GeometryFieldMethod field;
      ASSERT_TRUE(gpu.load(scene, error)) << error;
      ASSERT_TRUE(field.load(gpu, default_shader_dir(), error)) << error;
      field.settings().max_depth = 4;
      const Image image = clamped_to_display(render_image(field, scene.camera, kSize, kSize, 1));
      const ImageComparison c = compare_images(image, cpu);
      std::printf("%-28s PSNR %.2f dB, max |error| %.4f\n", what.c_str(), c.psnr, c.max_abs_error);
      // Measured on llvmpipe: diffuse 121-143 dB (the same float shading); mirrors and
      // dielectrics 44.6-143 dB, hollow-cylinder glass 40.5 dB (float GPU paths drift from the
      // double CPU ones where paths are chaotic: a few pixels at grazing and TIR bounces).
      EXPECT_GE(c.psnr, material == MaterialType::kDiffuse ? 100.0 : 38.0);
    }
  }
}

}  // namespace
}  // namespace gfield
