// gfield field MESH --image X.gimage.exr -o X.gfield.exr: the geometry field of a geometry image
// (docs/geometry-field.md).

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>

#include "geometry/parameterized_mesh.hpp"
#include "gfield/exr_io.hpp"
#include "preprocess/asset_build.hpp"
#include "preprocess/cli/asset_options.hpp"
#include "preprocess/cli/commands.hpp"

namespace gfield {

void add_field_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "field",
      "Build the geometry field of a geometry image: for every line through two of the 6N^2\n"
      "box-face samples on different faces, the image uvs of its hits, cast with Embree against\n"
      "the parameterised mesh beside the image (X.gimage.obj). Writes the compact field\n"
      "(format 3: the hit nearest each end of every line, the hits between for the few lines\n"
      "with more than two; docs/formats.md), or with --format 2 the layered one.");
  struct Arguments {
    std::string mesh, image, output;
    int samples = 24;
    int format = kFieldFormatVersion;
    int layers = kAutoLayers;
    bool half = false;
    bool full = false;
  };
  auto args = std::make_shared<Arguments>();
  cmd->add_option("MESH", args->mesh, "the mesh file the geometry image was built from")
      ->required();
  cmd->add_option("--image", args->image, "geometry image (X.gimage.exr, X.gimage.obj beside it)")
      ->required();
  cmd->add_option("-o,--output", args->output, "output geometry field (X.gfield.exr)")->required();
  cmd->add_option("--samples", args->samples,
                  "N, samples per side of each box face (" + std::to_string(kMinSamplesPerSide) +
                      " to " + std::to_string(kMaxSamplesPerSide) + ")")
      ->capture_default_str();
  add_field_format_options(cmd, args->format, args->layers);
  auto* half = cmd->add_flag("--half", args->half, "store U, V as half floats (default)");
  cmd->add_flag("--float", args->full, "store U, V as 32-bit floats")->excludes(half);
  cmd->callback([args] {
    std::string error;
    const bool use_half = !args->full;
    if (!check_field_size(args->samples, use_half, error)) {
      throw CommandError(args->output + ": " + error);
    }
    ExrAssetHeader header;
    if (!load_asset_header(args->image, header, error)) {
      throw CommandError(error);
    }
    if (header.format != "geometry-image") {
      throw CommandError(args->image + ": not a geometry image (format '" + header.format + "')");
    }
    const std::string mesh_name = std::filesystem::path(args->mesh).filename().string();
    if (!header.source.empty() && header.source != mesh_name) {
      throw CommandError(args->image + ": built from '" + header.source + "', not from '" +
                         mesh_name + "'");
    }
    GeometryImage image;
    ParameterizedMesh pm;
    const std::string obj = parameterized_mesh_path(args->image);
    if (!load_geometry_image(args->image, image, error) ||
        !load_parameterized_mesh_of(image, args->image, pm, error)) {
      throw CommandError(error);
    }
    if (!mesh_inside_box(pm, image.box)) {
      throw CommandError(obj + ": the mesh does not lie inside the geometry image's box (" +
                         args->image + "): they do not belong together");
    }
    const int side = sample_count(args->samples);
    std::printf("field N = %d: %d x %d sample pairs, ~%.0f MB in memory (%s)\n", args->samples,
                side, side, double(field_memory_estimate(args->samples, use_half)) / 1e6,
                use_half ? "half" : "float");
    std::fflush(stdout);
    FieldFileReport report;
    const FieldFileFormat format{args->format, args->layers,
                                 use_half ? ExrPrecision::kHalf : ExrPrecision::kFloat};
    if (!write_field_file(image, pm, args->samples, format, args->output, report, error)) {
      throw CommandError(error);
    }
    std::printf(
        "%zu rays, %zu hits (%.1f%%)\n%s\nBVH %.3f s, casts %.3f s (%.1f Mrays/s), write %.3f s\n"
        "wrote %s (%.1f MB)\n",
        report.build.rays, report.build.hits,
        100.0 * double(report.build.hits) / double(std::max<size_t>(1, report.build.rays)),
        field_layers_summary(report).c_str(), report.bvh_seconds, report.build.seconds,
        double(report.build.rays) / std::max(1e-9, report.build.seconds) / 1e6,
        report.write_seconds, args->output.c_str(), double(report.file_bytes) / 1e6);
  });
}

}  // namespace gfield
