// gfield-view: the geometry-field mirror-scene viewer (interactive) and headless renderer.

#include <chrono>
#include <cstdio>
#include <regex>

#include <CLI/CLI.hpp>

#include "gfield/image.hpp"
#include "gfield/printable.hpp"
#include "gfield/scene.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/methods/glass_cli.hpp"
#include "runtime/methods/image_space_cli.hpp"
#include "runtime/renderer.hpp"
#include "runtime/viewer.hpp"

namespace {

using namespace gfield;

/// Parses "WxH" (e.g. 256x256).
bool parse_size(const std::string& text, int& width, int& height) {
  std::smatch match;
  static const std::regex pattern(R"((\d{1,5})[xX](\d{1,5}))");
  if (!std::regex_match(text, match, pattern))
    return false;
  width = std::stoi(match[1].str());
  height = std::stoi(match[2].str());
  return width > 0 && height > 0 && width <= 16384 && height <= 16384;
}

int fail(const std::string& message, int code = 2) {
  std::fprintf(stderr, "gfield-view: %s\n", printable(message).c_str());
  return code;
}

int run_headless(const Scene& scene, const std::string& shader_dir, const RenderSettings& settings,
                 int width, int height, const std::string& out, int frames, bool bench) {
  std::string error;
  auto context = GlContext::create_headless(error);
  if (!context)
    return fail(error, kExitNoOpenGL);
  Renderer renderer;
  const auto load_start = std::chrono::steady_clock::now();
  if (!renderer.load(scene, shader_dir, error))
    return fail(error);
  const double load_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();
  FrameStats first;
  Image image = renderer.render_image(width, height, settings, &first);
  FrameStats total;
  for (int f = 1; f < frames; ++f)
    image = renderer.render_image(width, height, settings, &total);
  if (!out.empty() && !save_image(out, image, error))
    return fail(error);
  if (bench) {
    const int timed = frames > 1 ? frames - 1 : 1;
    const FrameStats& s = frames > 1 ? total : first;
    const double ms = s.milliseconds / timed;
    const double trace_ms = s.trace_milliseconds / timed;
    const double rays = double(s.secondary_rays) / timed;
    std::printf("renderer: %s (%s, %s)\n", context->renderer().c_str(), context->version().c_str(),
                context->platform().c_str());
    std::printf("scene: %s, %dx%d, mode %s, depth %d, %d spp, self-reflection %s\n",
                scene.filename.c_str(), width, height, lookup_mode_name(settings.mode),
                settings.max_depth, settings.samples_per_pixel,
                settings.self_reflection ? "on" : "off");
    std::printf("load + upload: %.3f s; texture memory %.1f MB\n", load_s,
                double(renderer.assets().texture_bytes()) / 1e6);
    std::printf("first frame: %.2f ms (includes shader warm-up)\n", first.milliseconds);
    std::printf("frame: %.2f ms (%.1f FPS) over %d frames: G-buffer %.2f ms, tracing %.2f ms\n", ms,
                1000.0 / ms, timed, s.gbuffer_milliseconds / timed, trace_ms);
    std::printf("traced pixels: %lld, secondary rays: %.0f (%.2f per traced pixel)\n",
                s.traced_pixels / timed, rays,
                s.traced_pixels > 0 ? rays / (double(s.traced_pixels) / timed) : 0.0);
    if (rays > 0)
      std::printf("tracing: %.1f ns per traced pixel per bounce\n", trace_ms * 1e6 / rays);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "gfield-view: real-time reflection and refraction with geometry fields "
      "(Li et al. 2006)"};
  app.footer(std::string("\nInteractive controls:\n") + viewer_shortcuts() +
             "\nExit codes: 0 ok, 2 bad input (scene, assets, shaders), 3 no OpenGL 4.5.");
  std::string scene_file, out, size_text, mode_text = "refined", method = "field";
  std::string shader_dir = default_shader_dir().string();
  bool headless = false, bench = false, no_self = false;
  int frames = 1;
  RenderSettings settings;
  app.add_option("scene", scene_file, "Scene file (JSON, docs/scenes.md)")->required();
  app.add_flag("--headless", headless, "Render without a window (EGL, no X) and exit");
  app.add_option("--out,-o", out, "Headless: write the picture to IMG.png or IMG.exr");
  app.add_option("--size", size_text, "Picture size WxH (default: the scene's)");
  std::vector<std::string> methods = {"field"};
  methods.insert(methods.end(), image_space_method_names().begin(),
                 image_space_method_names().end());
  methods.push_back("glass");
  app.add_option("--method", method, "Rendering method")->check(CLI::IsMember(methods));
  std::string glass_verge = "displaced";
  app.add_option("--glass-verge", glass_verge,
                 "glass: the hollow cylinder's verge displaced (the paper) or traced per pixel")
      ->check(CLI::IsMember({"displaced", "traced"}));
  auto image_space = std::make_shared<ImageSpaceOptions>();
  add_image_space_options(app, image_space);
  app.add_option("--mode", mode_text, "Geometry-field lookup: nearest, linear or refined")
      ->check(CLI::IsMember({"nearest", "linear", "refined"}));
  app.add_option("--depth", settings.max_depth,
                 "Reflections/refractions after the camera ray (as gfield render --depth)")
      ->check(CLI::Range(0, 64));
  app.add_option("--spp", settings.samples_per_pixel,
                 "Samples per pixel, stratified, at the strata centres (every method)")
      ->check(CLI::Range(1, 256));
  app.add_flag("--no-self-reflection", no_self,
               "Objects do not look up their own field (no self-reflection, no self-shadows)");
  app.add_option("--min-weight", settings.min_weight, "Branches below this weight are dropped")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--max-rays", settings.max_rays, "Secondary rays per pixel at most")
      ->check(CLI::Range(1, 256));
  app.add_option("--frames", frames,
                 "Headless: frames to render (timings average all but the first)")
      ->check(CLI::Range(1, 100000));
  app.add_flag("--bench", bench, "Headless: print ms per frame, the GL renderer and ray counts");
  app.add_option("--shaders", shader_dir,
                 "Folder of the GLSL shaders (default: $GFIELD_SHADER_DIR, else "
                 "../share/gfield/shaders beside the executable, else the source tree's)")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();
  std::string asset_dir;
  app.add_option("--assets", asset_dir,
                 "Folder of prebuilt assets: NAME.gimage.exr/.gfield.exr for mesh NAME.obj, found "
                 "there before those beside the mesh (gfield build MESH -o DIR/NAME)");
  CLI11_PARSE(app, argc, argv);

  parse_lookup_mode(mode_text, settings.mode);
  settings.self_reflection = !no_self;
  std::string error;
  Scene scene;
  if (!load_scene(scene_file, scene, error))
    return fail(error);
  if (!asset_dir.empty() && !use_asset_folder(asset_dir, scene, error))
    return fail("--assets " + error);
  if (!std::filesystem::is_regular_file(std::filesystem::path(shader_dir) / "field_trace.frag"))
    return fail(shader_dir +
                ": no gfield shaders here (field_trace.frag); set --shaders DIR or "
                "GFIELD_SHADER_DIR");
  int width = scene.width, height = scene.height;
  if (!size_text.empty() && !parse_size(size_text, width, height))
    return fail("--size " + size_text + ": expected WxH with 1..16384 pixels per side");
  if (headless) {
    if (out.empty() && !bench)
      return fail("--headless needs --out IMG.png|exr or --bench");
    if (!out.empty()) {
      const std::string ext = std::filesystem::path(out).extension().string();
      if (ext != ".png" && ext != ".exr")
        return fail(out + ": the picture must be .png or .exr");
    }
    if (method == "glass") {
      GlassSettings glass;
      glass.samples_per_pixel = settings.samples_per_pixel;
      glass.trace_verge = glass_verge == "traced";
      return run_glass_headless(scene, shader_dir, glass, width, height, out, frames, bench);
    }
    image_space->settings.samples_per_pixel = settings.samples_per_pixel;
    if (method != "field" || !image_space->side_by_side.empty() || !image_space->reference.empty())
      return run_image_space_headless(scene, shader_dir, method, *image_space, settings, width,
                                      height, out, frames, bench);
    return run_headless(scene, shader_dir, settings, width, height, out, frames, bench);
  }
  return run_viewer(scene, shader_dir, settings, width, height);
}
