// gfield export-gltf SCENE -o OUT.glb [--segments N]: a scene as a binary glTF 2.0 file
// (geometry/gltf_writer.hpp), read back by every gfield command that reads scenes.

#include <CLI/CLI.hpp>

#include <cstdio>

#include "geometry/gltf_writer.hpp"
#include "geometry/scene_file.hpp"
#include "geometry/shape_tessellation.hpp"
#include "gfield/printable.hpp"
#include "preprocess/cli/commands.hpp"
#include "preprocess/cli/path_options.hpp"

namespace gfield {

void add_export_gltf_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export-gltf",
      "Write a scene (JSON or glTF) as a binary glTF 2.0 file: meshes with their texture\n"
      "coordinates, colours and textures; quads, spheres, boxes, cylinders, slabs and hollow\n"
      "cylinders as triangles (--segments), their procedural textures baked; materials (mirror:\n"
      "metallic; dielectric: KHR_materials_transmission/ior/volume, not double-sided); the\n"
      "camera, KHR_lights_punctual lights, and the environment, ambient light and image size as\n"
      "extras.");
  auto scene_file = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto allow_outside = std::make_shared<bool>(false);
  auto options = std::make_shared<GltfExportOptions>();
  cmd->add_option("SCENE", *scene_file, "scene file (.json, .gltf, .glb)")->required();
  cmd->add_option("-o,--output", *output, "the binary glTF file to write (.glb)")->required();
  cmd->add_option("--segments", options->segments,
                  "segments around spheres (half as many rings), cylinders and hollow cylinders")
      ->check(CLI::Range(kMinShapeSegments, kMaxShapeSegments))
      ->capture_default_str();
  add_outside_paths_option(cmd, *allow_outside);
  cmd->callback([scene_file, output, allow_outside, options] {
    Scene scene;
    std::vector<std::string> warnings;
    std::string error;
    if (!load_scene_file(*scene_file, scene, warnings, error, outside_paths(*allow_outside)) ||
        !write_gltf_scene(scene, *output, *options, error)) {
      throw CommandError(error);
    }
    print_warnings(warnings);
    std::printf("%s: %zu objects, %zu lights\n", printable(*output).c_str(), scene.objects.size(),
                scene.lights.size());
  });
}

}  // namespace gfield
