// gfield render SCENE.json -o OUT.exr|png [--spp 8] [--depth 10] [--dielectric MODE] [--size WxH]
// [--camera ...] [--seed N | --strata-centres]: the reference ray tracer.

#include <unistd.h>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "geometry/scene_file.hpp"
#include "gfield/camera_text.hpp"
#include "gfield/image.hpp"
#include "gfield/scene.hpp"
#include "preprocess/cli/commands.hpp"
#include "preprocess/cli/path_options.hpp"
#include "preprocess/reference_tracer.hpp"

namespace gfield {
namespace {

struct RenderArgs {
  std::string scene;
  std::string output;
  int spp = 8;
  int depth = 10;
  std::string dielectric = "full";
  std::string size;
  std::string camera;
  std::uint64_t seed = 1;
  bool strata_centres = false;
  bool quiet = false;
  bool allow_outside_paths = false;
};

void run_render(const RenderArgs& args) {
  const std::string ext = args.output.size() >= 4 ? args.output.substr(args.output.size() - 4) : "";
  if (ext != ".exr" && ext != ".png" && ext != ".EXR" && ext != ".PNG") {
    throw CommandError(args.output + ": output must end in .exr or .png");
  }
  RenderOptions options;
  options.samples_per_pixel = args.spp;
  options.max_depth = args.depth;
  options.seed = args.seed;
  options.jitter = !args.strata_centres;
  if (!parse_dielectric_mode(args.dielectric, options.dielectric)) {
    throw CommandError("--dielectric " + args.dielectric +
                       ": expected full, refract-only or tir-only");
  }
  if (!args.size.empty()) {
    int w = 0, h = 0;
    char tail = 0;
    if (std::sscanf(args.size.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w <= 0 || h <= 0) {
      throw CommandError("--size " + args.size + ": expected WIDTHxHEIGHT, e.g. 512x512");
    }
    options.width = w;
    options.height = h;
  }
  Scene scene;
  std::string error;
  std::vector<std::string> warnings;
  if (!load_scene_file(args.scene, scene, warnings, error, outside_paths(args.allow_outside_paths)))
    throw CommandError(error);
  print_warnings(warnings);
  if (!args.camera.empty() && !parse_camera_text(args.camera, scene.camera, error))
    throw CommandError("--camera " + args.camera + ": " + error);
  const int width = options.width > 0 ? options.width : scene.width;
  const int height = options.height > 0 ? options.height : scene.height;
  if (!check_render_budget(width, height, options.samples_per_pixel, error)) {
    throw CommandError(args.scene + ": " + error);
  }
  ReferenceTracer tracer;
  if (!tracer.build(scene, error))
    throw CommandError(error);
  options.progress = !args.quiet && isatty(STDERR_FILENO);
  RenderStats stats;
  const Image image = tracer.render(options, &stats);
  if (!save_image(args.output, image, error))
    throw CommandError(error);
  if (!args.quiet) {
    std::printf(
        "%s: %dx%d, %d spp, depth %d, %s: %.2f s, %.2f Mrays (%.1f%% camera), %.2f Mrays/s\n",
        args.output.c_str(), width, height, options.samples_per_pixel, options.max_depth,
        dielectric_mode_name(options.dielectric), stats.seconds, double(stats.total_rays()) / 1e6,
        100.0 * double(stats.camera_rays) / double(std::max<std::uint64_t>(1, stats.total_rays())),
        double(stats.total_rays()) / 1e6 / std::max(stats.seconds, 1e-9));
  }
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "render",
      "Render a scene (docs/scenes.md) with the reference ray tracer: Whitted-style on\n"
      "Embree, exact Fresnel, total internal reflection, absorption, stratified\n"
      "supersampling; deterministic for a given seed.");
  auto args = std::make_shared<RenderArgs>();
  cmd->add_option("SCENE", args->scene, "scene file (.json, or a glTF file: .gltf, .glb)")
      ->required();
  cmd->add_option("-o,--output", args->output, "output image (.exr linear float, .png sRGB)")
      ->required();
  cmd->add_option("--spp", args->spp, "samples per pixel (stratified)")
      ->check(CLI::Range(1, std::numeric_limits<int>::max()))
      ->capture_default_str();
  cmd->add_option("--depth", args->depth, "reflections/refractions per path")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_option("--dielectric", args->dielectric,
                  "full | refract-only | tir-only (reflected rays only under TIR)")
      ->capture_default_str();
  cmd->add_option("--size", args->size, "WIDTHxHEIGHT, overrides the scene's image size");
  cmd->add_option("--camera", args->camera,
                  "EX,EY,EZ,TX,TY,TZ[,UX,UY,UZ[,FOV]]: eye, target, up, vertical field of view in "
                  "degrees, overrides the scene's camera (gfield-view's screenshots print theirs)");
  cmd->add_option("--seed", args->seed, "seed of the sample jitter")->capture_default_str();
  cmd->add_flag("--strata-centres", args->strata_centres,
                "no jitter: samples at the strata centres (1 spp: the pixel centre), the positions "
                "gfield-view --spp samples");
  cmd->add_flag("-q,--quiet", args->quiet, "no progress bar, no summary line");
  add_outside_paths_option(cmd, args->allow_outside_paths);
  cmd->callback([args] { run_render(*args); });
}

}  // namespace gfield
