#include "runtime/headless.hpp"

#include <algorithm>
#include <cstdio>

#include "gfield/image_metrics.hpp"
#include "gfield/printable.hpp"
#include "gfield/stopwatch.hpp"
#include "runtime/asset_memory.hpp"
#include "runtime/frame_timing.hpp"
#include "runtime/gl_context.hpp"

namespace gfield {
namespace {

int fail(const std::string& message, int code = 2) {
  std::fprintf(stderr, "gfield-view: %s\n", printable(message).c_str());
  return code;
}

/// One method's picture and its timings.
struct MethodRun {
  Image image;
  FrameStats first;          ///< the first frame (shader warm-up included)
  FrameTimes rest;           ///< with more than one frame: the timed frames after the warm-up
  double rest_cpu_ms = 0.0;  ///< CPU time of this process per frame after the first (all threads)
};

/// Selects (loads) the method named `name`.
bool select_method(ViewSession& session, const std::string& name, std::string& error) {
  const int index = session.find(name);
  if (index < 0) {
    error = "--method " + name + ": no such method";
    return false;
  }
  return session.select(index, error);
}

/// Renders the selected method's picture; with o.frames > 1, the frames a method that times
/// itself asks for (Method::measuring: the field method's --pass auto trial, at most
/// kMaxWarmupFrames), warm-up frames (frame_timing.hpp) and o.frames - 1 timed frames after the
/// first.
MethodRun render_frames(ViewSession& session, const HeadlessOptions& o) {
  Method& method = session.method(session.current());
  const Camera& camera = session.scene().scene().camera;
  MethodRun run;
  run.image = render_image(method, camera, o.width, o.height, o.samples_per_pixel, &run.first);
  if (o.frames == 1)
    return run;
  const double cpu_start = process_cpu_ms();
  int measuring = 0;
  for (; measuring < kMaxWarmupFrames && method.measuring(); ++measuring)
    render_image(method, camera, o.width, o.height, o.samples_per_pixel);
  run.rest = time_frames(
      [&](FrameStats* stats) {
        run.image = render_image(method, camera, o.width, o.height, o.samples_per_pixel, stats);
      },
      o.frames - 1);
  run.rest.warmup_frames += measuring;
  run.rest_cpu_ms = (process_cpu_ms() - cpu_start) / double(run.rest.warmup_frames + o.frames - 1);
  return run;
}

/// "median M ms (min A, max B[, spread S%: noisy])".
std::string summary_text(const TimeSummary& t) {
  char text[128];
  std::snprintf(text, sizeof(text), "median %.2f ms (min %.2f, max %.2f%s)", t.median, t.min, t.max,
                t.noisy() ? ", spread above 10%: noisy" : "");
  return text;
}

/// The frame time lines: the first frame, and the timed frames' wall and GPU times apart.
void print_frame_times(const MethodRun& run, const HeadlessOptions& o) {
  std::printf("first frame: %.2f ms (includes shader warm-up)\n", run.first.milliseconds);
  const int timed = o.frames > 1 ? o.frames - 1 : 1;
  const FrameStats& s = o.frames > 1 ? run.rest.stats : run.first;
  const TimeSummary wall = o.frames > 1
                               ? summarize(run.rest.wall_ms)
                               : TimeSummary{s.milliseconds, s.milliseconds, s.milliseconds};
  std::printf("frame: %.2f ms (%.1f FPS), the median of %d frame(s)", wall.median,
              1000.0 / std::max(wall.median, 1e-6), timed);
  for (size_t k = 0; k < s.parts_ms.size(); ++k)
    std::printf("%s %s %.2f ms", k == 0 ? ":" : ",", s.parts_ms[k].first.c_str(),
                s.parts_ms[k].second / timed);
  if (o.frames > 1)  // on a GL that runs on the CPU (llvmpipe): what another load does not change
    std::printf("; CPU %.2f ms per frame", run.rest_cpu_ms);
  std::printf("\n");
  if (o.frames > 1)
    std::printf("wall: %s; GPU: %s; after %d warm-up frame(s)\n", summary_text(wall).c_str(),
                summary_text(summarize(run.rest.gpu_ms)).c_str(), run.rest.warmup_frames);
  for (size_t k = 0; k < s.gpu_parts_ms.size(); ++k)
    std::printf("%s %s %.2f ms%s", k == 0 ? "GPU per pass:" : ",", s.gpu_parts_ms[k].first.c_str(),
                s.gpu_parts_ms[k].second / timed, k + 1 == s.gpu_parts_ms.size() ? "\n" : "");
}

void print_bench(const Method& method, const MethodRun& run, const HeadlessOptions& o) {
  const int timed = o.frames > 1 ? o.frames - 1 : 1;
  const FrameStats& s = o.frames > 1 ? run.rest.stats : run.first;
  std::printf("%s: %dx%d, %d spp\n", method.info().name.c_str(), o.width, o.height,
              o.samples_per_pixel);
  print_frame_times(run, o);
  // Counts per sample (one frame is samples_per_pixel samples).
  FrameStats per_sample;
  const double samples = double(timed) * double(std::max(1, o.samples_per_pixel));
  for (const auto& [name, value] : s.counts)
    per_sample.add_count(name, value / samples);
  for (const auto& [name, value] : s.parts_ms)
    per_sample.add_part(name, value / samples);
  for (size_t k = 0; k < per_sample.counts.size(); ++k)
    std::printf("%s%s %.0f", k == 0 ? "per sample: " : ", ", per_sample.counts[k].first.c_str(),
                per_sample.counts[k].second);
  if (!per_sample.counts.empty())
    std::printf("\n");
  const std::string summary = method.summary(per_sample);
  if (!summary.empty())
    std::printf("%s\n", summary.c_str());
  const std::string status = method.status();
  if (!status.empty())
    std::printf("%s\n", status.c_str());
}

/// Prints PSNR and SSIM against o.reference and writes the heat map; false on a bad reference.
bool compare_with_reference(Image image, const HeadlessOptions& o, std::string& error) {
  Image reference;
  if (!load_image(o.reference, reference, error))
    return false;
  if (reference.width != image.width || reference.height != image.height) {
    error = o.reference + ": " + std::to_string(reference.width) + "x" +
            std::to_string(reference.height) + ", the render is " + std::to_string(image.width) +
            "x" + std::to_string(image.height);
    return false;
  }
  // The frame is radiance; against a display reference (PNG) it is compared as a PNG of it.
  const MetricScale scale = match_metric_scale(image, "", reference, o.reference);
  const ImageComparison c = compare_images(image, reference);
  std::printf("%s vs %s (%s): PSNR %.2f dB, SSIM %.4f, mean |error| %.4f\n", o.method.c_str(),
              o.reference.c_str(), metric_scale_name(scale), c.psnr, c.ssim, c.mean_abs_error);
  return o.difference.empty() ||
         save_image(o.difference, error_heatmap(image, reference, o.difference_scale), error);
}

Image side_by_side(const Image& left, const Image& right) {
  Image both(left.width + right.width, left.height);
  for (int y = 0; y < left.height; ++y) {
    for (int x = 0; x < left.width; ++x)
      both.at(x, y) = left.at(x, y);
    for (int x = 0; x < right.width; ++x)
      both.at(left.width + x, y) = right.at(x, y);
  }
  return both;
}

/// The headless run with a current context.
int render_headless(ViewSession& session, const Scene& scene,
                    const std::filesystem::path& shader_dir, const HeadlessOptions& options,
                    const GlContext& context) {
  std::string error;
  HeadlessOptions o = options;
  o.width = o.width > 0 ? o.width : scene.width;
  o.height = o.height > 0 ? o.height : scene.height;
  const Stopwatch load_clock;
  if (!session.load(scene, shader_dir, error) || !select_method(session, o.method, error))
    return fail(error);
  const double load_s = load_clock.seconds();
  const MethodRun run = render_frames(session, o);
  if (o.bench) {
    std::printf("renderer: %s (%s, %s)\n", context.renderer().c_str(), context.version().c_str(),
                context.platform().c_str());
    std::printf("scene: %s; load + upload %.3f s; texture memory %.1f MB\n%s",
                scene.filename.c_str(), load_s,
                double(session.scene().assets().texture_bytes()) / 1e6,
                asset_memory_lines(scene, session.scene().assets()).c_str());
    print_bench(session.method(session.current()), run, o);
  }
  if (!o.reference.empty() && !compare_with_reference(run.image, o, error))
    return fail(error);
  Image picture = run.image;
  if (!o.side_by_side.empty()) {
    if (!select_method(session, o.side_by_side, error))
      return fail(error);
    const MethodRun second = render_frames(session, o);
    if (o.bench)
      print_bench(session.method(session.current()), second, o);
    picture = side_by_side(picture, second.image);
  }
  if (!o.out.empty() && !save_image(o.out, picture, error))
    return fail(error);
  return 0;
}

}  // namespace

int run_headless(ViewSession& session, const Scene& scene, const std::filesystem::path& shader_dir,
                 const HeadlessOptions& options) {
  std::string error;
  auto context = GlContext::create_headless(error);
  if (!context)
    return fail(error, kExitNoOpenGL);
  const int code = render_headless(session, scene, shader_dir, options, *context);
  session.release();  // while the context is current
  return code;
}

}  // namespace gfield
