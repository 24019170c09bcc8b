#pragma once
// gfield-view --export-web DIR: a folder any static web server can serve, holding the web
// player (web/player: index.html and its modules) and a scene as the player draws it with the
// geometry-field method (docs/web.md; layout in docs/formats.md, "Web scene"):
//   - scene.json: format "gfield-web", version, the camera and picture size, the scene
//     uniforms, per object what rasterising it needs (matrices, shape, its mesh), and where each
//     block, texture and mesh lies in scene.bin.gz;
//   - scene.bin.gz: one gzip stream of the GPU scene's own bytes, read back from the runtime's
//     buffers and textures (so the browser draws exactly what gfield-view draws): the objects'
//     and lights' std140 blocks, the geometry images, fields (8 bits), their line words, albedo,
//     the meshes' own textures, the environment, the BVHs (the page's bvh method), the rasterised
//     meshes and the proxy cube;
//   - shaders/: the stages the player runs, in GLSL ES 3.00 (runtime/glsl_es.hpp);
//   - vendor/: three.js's core and three-mesh-bvh, the page's three-mesh-bvh method, when
//     web/node_modules holds them (scripts/install-web-deps.sh; scene.json "peers" says).
// The folder appears whole or not at all (written beside DIR, then renamed; an earlier export
// in DIR is replaced).

#include <filesystem>
#include <string>

#include "runtime/gpu_scene.hpp"

namespace gfield {

/// Version of the web scene layout (scene.json "version"; the player refuses any other).
inline constexpr int kWebSceneVersion = 1;

/// What the export writes besides the scene's own data.
struct WebExportOptions {
  std::filesystem::path shader_dir;    ///< the runtime's shaders/
  std::filesystem::path player_dir;    ///< web/player: index.html and its modules
  std::filesystem::path node_modules;  ///< web/node_modules: three, three-mesh-bvh (optional)
  std::string scene_name;              ///< shown by the page ("mirror-torus-instances")
  int width = 0, height = 0;           ///< the picture the page draws by default
};

/// Writes the web folder `out` for `gpu`, a loaded GPU scene whose assets hold images and 8-bit
/// fields (where the mesh has them), source meshes and BVHs for every mesh (a current GL
/// context). False with a one-line
/// "FILE: problem" when the scene exceeds what WebGL2 holds (objects, lights, texture sizes),
/// a file cannot be read or written, or `out` exists and is not an earlier export; then
/// nothing is left behind.
bool export_web(const GpuScene& gpu, const std::filesystem::path& out,
                const WebExportOptions& options, std::string& error);

/// gfield-view SCENE --export-web DIR: a headless context, the scene's images, 8-bit fields,
/// source meshes and BVHs loaded (a mesh without its assets noted on stderr: the player traces
/// it by its BVH, as gfield-view does), export_web. Returns the exit code: 0; 2 for bad input
/// or kExitNoOpenGL, with a one-line `error`.
int run_export_web(const Scene& scene, const std::filesystem::path& out,
                   const WebExportOptions& options, std::string& error);

}  // namespace gfield
