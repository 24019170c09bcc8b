#pragma once
// gfield-view --headless: any registered method renders the scene's camera into a picture file
// through a ViewSession (EGL, no window), optionally timed (--bench), compared with a reference
// picture (PSNR, SSIM, an error heat map) and drawn beside a second method (--side-by-side).

#include <filesystem>
#include <string>

#include "gfield/scene.hpp"
#include "runtime/view_session.hpp"

namespace gfield {

struct HeadlessOptions {
  std::string method = "field";
  int width = 0, height = 0;  ///< the picture (the scene's size when 0)
  int samples_per_pixel = 1;  ///< stratified, at the strata centres
  int frames = 1;             ///< frames rendered; timings average all but the first
  bool bench = false;         ///< print the GL renderer, times and counts
  std::string out;            ///< .png or .exr ("": none)
  std::string side_by_side;   ///< a second method drawn to the right (a 2W x H picture)
  std::string reference;      ///< a picture to compare with
  std::string difference;     ///< where to write the error heat map against `reference`
  float difference_scale = 0.25f;
};

/// Renders `scene` with `session`'s methods as `options` say. Returns the exit code: 0, 2 with a
/// one-line message on stderr for bad input (scene, assets, shaders, pictures), or
/// kExitNoOpenGL.
int run_headless(ViewSession& session, const Scene& scene, const std::filesystem::path& shader_dir,
                 const HeadlessOptions& options);

}  // namespace gfield
