// gfield-view: the methods of runtime/method_registry.cpp in an interactive window or headless.

#include <cstdio>
#include <filesystem>
#include <regex>

#include <CLI/CLI.hpp>

#include "gfield/camera_text.hpp"
#include "gfield/printable.hpp"
#include "gfield/scene.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/headless.hpp"
#include "runtime/method_cli.hpp"
#include "runtime/method_registry.hpp"
#include "runtime/scene_assets.hpp"
#include "runtime/shader_program.hpp"
#include "runtime/view_session.hpp"
#include "runtime/viewer.hpp"
#include "runtime/web_export.hpp"

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

int fail(const std::string& message) {
  std::fprintf(stderr, "gfield-view: %s\n", printable(message).c_str());
  return 2;
}

struct Arguments {
  std::string scene_file, size_text, shader_dir = default_shader_dir().string(), asset_dir;
  std::string camera_text;
  std::string export_web;
  bool headless = false;
  bool allow_outside_paths = false;
  bool rebuild_stale = false;
  HeadlessOptions headless_options;
};

void add_common_options(CLI::App& app, Arguments& a) {
  HeadlessOptions& h = a.headless_options;
  std::string methods;
  for (const std::string& name : method_names())
    methods += (methods.empty() ? "" : ", ") + name;
  app.add_option("scene", a.scene_file,
                 "Scene file (JSON, docs/scenes.md, or glTF 2.0: .gltf, .glb)")
      ->required();
  app.add_option("--method", h.method, "Rendering method: " + methods)
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  app.add_flag("--headless", a.headless, "Render without a window (EGL, no X) and exit");
  app.add_option("--out,-o", h.out, "Headless: write the picture to IMG.png or IMG.exr");
  app.add_option("--size", a.size_text, "Picture size WxH (default: the scene's)");
  app.add_option("--camera", a.camera_text,
                 "Camera EX,EY,EZ,TX,TY,TZ[,UX,UY,UZ[,FOV]]: eye, target, up, vertical field of "
                 "view in degrees (default: the scene's; a screenshot (key p) prints its own)");
  app.add_option("--spp", h.samples_per_pixel,
                 "Samples per pixel, stratified, at the strata centres (every method)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  app.add_option("--frames", h.frames,
                 "Headless: N frames: the first, then (N above 1) warm-up frames until two "
                 "agree within 10% and N-1 timed ones (their median and range)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  app.add_flag("--bench", h.bench,
               "Headless: print ms per frame (wall and GPU apart, and per pass), the GL renderer "
               "and counts");
  app.add_option("--side-by-side", h.side_by_side,
                 "Headless: draw this second method to the right of the first")
      ->check(CLI::IsMember(method_names()));
  app.add_option("--reference", h.reference,
                 "Headless: compare with this picture (.exr/.png), print PSNR and SSIM (against a "
                 "PNG/JPEG on the values a PNG stores: sRGB, 8 bits, as ImageMagick does)")
      ->check(CLI::ExistingFile);
  app.add_option("--diff", h.difference,
                 "Headless: write the error heat map against --reference here (.png/.exr)");
  app.add_option("--diff-scale", h.difference_scale, "Error shown white in the heat map")
      ->capture_default_str();
  app.add_option("--export-web", a.export_web,
                 "Write DIR: the web player (index.html) and the scene as it draws it with "
                 "geometry fields, for any static web server (docs/web.md); no window")
      ->type_name("DIR");
  app.add_option("--shaders", a.shader_dir,
                 "Folder of the GLSL shaders (default: $GFIELD_SHADER_DIR, else "
                 "../share/gfield/shaders beside the executable, else the source tree's)")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();
  app.add_option("--assets", a.asset_dir,
                 "Folder of prebuilt assets: NAME.gimage.exr/.gfield.exr for mesh NAME.obj, found "
                 "there before those beside the mesh (gfield build MESH -o DIR/NAME); the assets "
                 "of glTF meshes are built there on demand (default: beside the glTF file)");
  app.add_flag("--rebuild-stale", a.rebuild_stale,
               "Rebuild (gfield build MESH -o NAME, default options) an asset built from another "
               "mesh or an older version of its mesh, instead of refusing it");
  app.add_flag("--allow-outside-paths", a.allow_outside_paths,
               "Read the files that a glTF file or a mesh names outside its folder, and that a "
               "scene names outside its root (docs/scenes.md, \"Confined paths\")");
}

/// Checks what the options say against each other, before anything is loaded (a glTF scene's
/// assets may take a minute to build); "" when all is well.
std::string check_options(Arguments& a) {
  HeadlessOptions& h = a.headless_options;
  if (!a.size_text.empty() && !parse_size(a.size_text, h.width, h.height))
    return "--size " + a.size_text + ": expected WxH with 1..16384 pixels per side";
  if (!std::filesystem::is_regular_file(std::filesystem::path(a.shader_dir) / "field_trace.frag"))
    return a.shader_dir +
           ": no gfield shaders here (field_trace.frag); set --shaders DIR or GFIELD_SHADER_DIR";
  if (!a.headless)
    return "";
  if (h.out.empty() && !h.bench)
    return "--headless needs --out IMG.png|exr or --bench";
  const std::string ext = std::filesystem::path(h.out).extension().string();
  if (!h.out.empty() && ext != ".png" && ext != ".exr")
    return h.out + ": the picture must be .png or .exr";
  return "";
}

/// Loads the scene and checks the view against it; "" when all is well.
std::string load_and_check_scene(Arguments& a, Scene& scene) {
  std::string error;
  const OutsidePaths outside =
      a.allow_outside_paths ? OutsidePaths::kAllowed : OutsidePaths::kRefused;
  if (!load_view_scene(a.scene_file, a.asset_dir, outside, a.rebuild_stale, scene, error))
    return error;
  if (!a.camera_text.empty() && !parse_camera_text(a.camera_text, scene.camera, error))
    return "--camera " + a.camera_text + ": " + error;
  HeadlessOptions& h = a.headless_options;
  if (a.size_text.empty()) {
    h.width = scene.width;
    h.height = scene.height;
  }
  const std::string problem = camera_resolution_problem(scene.camera);
  if (problem.empty())
    return "";
  return a.camera_text.empty() ? a.scene_file + ": /camera/fov: " + problem
                               : "--camera " + a.camera_text + ": " + problem;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "gfield-view: real-time reflection and refraction with geometry fields (Li et al. 2006) "
      "and the methods they are measured against"};
  app.footer(std::string("\nInteractive controls:\n") + viewer_shortcuts() +
             "\nExit codes: 0 ok, 2 bad input (scene, assets, shaders), 3 no OpenGL 4.5.");
  Arguments a;
  add_common_options(app, a);
  ViewSession session;
  std::vector<Method*> methods;
  for (int k = 0; k < session.method_count(); ++k)
    methods.push_back(&session.method(k));
  add_method_options(app, methods);
  CLI11_PARSE(app, argc, argv);

  Scene scene;
  std::string error = check_options(a);
  if (error.empty())
    error = load_and_check_scene(a, scene);
  if (!error.empty())
    return fail(error);
  if (!a.export_web.empty()) {
    WebExportOptions web;
    web.shader_dir = a.shader_dir;
    web.player_dir = std::filesystem::path(a.shader_dir) / ".." / "web" / "player";
    web.node_modules = std::filesystem::path(a.shader_dir) / ".." / "web" / "node_modules";
    web.scene_name = std::filesystem::path(a.scene_file).stem().string();
    web.width = a.headless_options.width;
    web.height = a.headless_options.height;
    const int code = run_export_web(scene, a.export_web, web, error);
    if (code != 0)
      fail(error);
    return code;
  }
  if (a.headless)
    return run_headless(session, scene, a.shader_dir, a.headless_options);
  ViewerOptions viewer;
  viewer.method = session.find(a.headless_options.method);
  viewer.width = a.headless_options.width;
  viewer.height = a.headless_options.height;
  viewer.command = "gfield-view " + a.scene_file +
                   (a.asset_dir.empty() ? "" : " --assets " + a.asset_dir) +
                   (a.allow_outside_paths ? " --allow-outside-paths" : "");
  return run_viewer(session, scene, a.shader_dir, viewer);
}
