#pragma once
// The command-line options of the asset pipeline, shared by `gfield build`, `batch` and `assets`
// (what they mean and their checks: asset_arguments.hpp).

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include "gfield/gpu_storage.hpp"
#include "preprocess/asset_arguments.hpp"
#include "preprocess/asset_report.hpp"
#include "preprocess/cli/path_options.hpp"
#include "preprocess/verify.hpp"

namespace gfield {

/// --size, --max-image-error and --proxy-above of `gfield image`, `build` and `batch`.
inline void add_image_size_options(CLI::App* cmd, std::string& size, double& max_image_error,
                                   size_t& proxy_above) {
  const std::string sizes =
      std::to_string(kAutoImageSizes[0]) + ", or " + std::to_string(kAutoImageSizes[1]);
  cmd->add_option("--size", size,
                  "geometry image texels per side (" + std::to_string(kMinImageSize) + " to " +
                      std::to_string(kMaxImageSize) + "), or auto: " + sizes +
                      " where the smaller one's\nmean mesh -> image distance exceeds "
                      "--max-image-error")
      ->check(CLI::Validator([](std::string& text) { return image_size_problem(text); }, "auto|N"))
      ->capture_default_str();
  cmd->add_option("--max-image-error", max_image_error,
                  "--size auto: the mean mesh -> image distance to reach, percent of the mesh's "
                  "diagonal")
      ->check(CLI::Validator(
          [](std::string& text) {
            size_t end = 0;
            double value = 0.0;
            try {
              value = std::stod(text, &end);
            } catch (const std::exception&) {
            }
            return max_image_error_problem(end == text.size() ? value : std::nan(""), text);
          },
          "PERCENT"))
      ->capture_default_str();
  cmd->add_option("--proxy-above", proxy_above,
                  "a mesh of more faces is charted as a simplified proxy of half as many, the "
                  "image's texels\nprojected onto the full surface (0: never)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

/// --format and --layers of `gfield field`, `build` and `batch`.
inline void add_field_format_options(CLI::App* cmd, int& format, int& layers) {
  cmd->add_option("--format", format,
                  "field format: 3, compact (every hit of each line up to " +
                      std::to_string(kMaxLineHits) +
                      "), or 2, layered (K hits per ray, --layers; for comparison)")
      ->check(CLI::IsMember({kFieldFormatVersion, kLayeredFieldVersion}))
      ->capture_default_str();
  cmd->add_option("--layers", layers,
                  "--format 2: K, hits stored per ray (1 to " + std::to_string(kMaxFieldLayers) +
                      "; default: the smallest K that stores every hit of 99.9% of the lines)")
      ->check(CLI::Range(1, kMaxFieldLayers));
}

/// Adds --size, --max-image-error, --samples, --format, --layers, --half/--float, --verify-rays,
/// --method,
/// --components, --allow-outside-paths to `cmd`.
inline void add_asset_options(CLI::App* cmd, const std::shared_ptr<AssetArguments>& args) {
  add_image_size_options(cmd, args->size, args->max_image_error, args->proxy_above);
  cmd->add_option("--samples", args->samples,
                  "N, field samples per side of each box face (" +
                      std::to_string(kMinSamplesPerSide) + " to " +
                      std::to_string(kMaxSamplesPerSide) + ")")
      ->capture_default_str();
  add_field_format_options(cmd, args->format, args->layers);
  auto* half = cmd->add_flag("--half", args->half, "field U, V as half floats (default)");
  cmd->add_flag("--float", args->full, "field U, V as 32-bit floats")->excludes(half);
  cmd->add_option("--verify-rays", args->verify_rays,
                  "rays per family for the report's accuracy (0: skip)")
      ->capture_default_str();
  cmd->add_option("--method", args->method, "parameterisation: auto, orbifold, square")
      ->check(CLI::IsMember({"auto", "orbifold", "square"}))
      ->capture_default_str();
  cmd->add_option("--components", args->components, "all (packed charts) or largest")
      ->check(CLI::IsMember({"all", "largest"}))
      ->capture_default_str();
  add_outside_paths_option(cmd, args->allow_outside_paths);
}

/// "; proxy of 99865 faces" where the image was charted on a proxy (mesh_proxy.hpp), "; proxy
/// of 99865 faces rejected" where one was tried and not kept, else "".
inline std::string proxy_text(const ProxyReport& proxy) {
  if (proxy.faces == 0)
    return "";
  return "; proxy of " + std::to_string(proxy.faces) + (proxy.used ? " faces" : " faces rejected");
}

/// "stages: mesh 0.02 s, image 1.87 s (+ write 0.25 s), field 0.81 s (+ write 0.35 s), verify
/// 1.10 s": a build's stage times, one line.
inline std::string stage_summary(const AssetReport& report) {
  const AssetStageSeconds& s = report.stage_seconds;
  char line[256];
  std::snprintf(line, sizeof(line),
                "stages: mesh %.2f s, image %.2f s (+ write %.2f s), field %.2f s (+ write %.2f "
                "s), verify %.2f s",
                s.mesh, s.image, s.image_write, s.field, s.field_write, s.verify);
  return line;
}

/// One line: what an asset build produced and how accurate it is.
inline std::string asset_summary(const AssetReport& report) {
  char line[512];
  const FieldFileReport& f = report.geometry_field;
  std::snprintf(line, sizeof(line),
                "image %d^2 (%s%s), field N = %d, format %d, K = %d (casts %.2f s, write %.2f s), "
                "GPU %.1f MB (image) + %.1f MB (field at 8 bits)",
                report.image_size, report.geometry_image.route.c_str(),
                proxy_text(report.geometry_image.proxy).c_str(), f.samples_per_side, f.format,
                f.layers, f.build.seconds, f.write_seconds,
                double(geometry_image_gpu_bytes(report.image_size)) / 1e6,
                double(f.gpu_bytes[0]) / 1e6);
  std::string text = line;
  if (report.accuracy) {
    const ReferenceAccuracy& r = report.accuracy->described();
    const AccuracyStats& refined = r.families.at("box_rays").at("refined");
    const glm::dvec2 interval = agreement_interval(refined.agree, refined.rays);
    std::snprintf(line, sizeof(line),
                  ", table hit/miss %.3f%%, refined hit/miss %.3f%% (95%%: %.2f-%.2f%%) median "
                  "%.4f%% p95 %.4f%%",
                  100.0 * r.table.hit_agreement(), 100.0 * refined.hit_agreement(),
                  100.0 * interval.x, 100.0 * interval.y, refined.position_median,
                  refined.position_p95);
    text += line;
  }
  return text;
}

}  // namespace gfield
