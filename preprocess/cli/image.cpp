// gfield image MESH -o OUT.gimage.exr: the geometry image of a mesh (docs/geometry-image.md).

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/parameterized_mesh.hpp"
#include "gfield/atomic_file.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/printable.hpp"
#include "preprocess/asset_build.hpp"
#include "preprocess/cli/asset_options.hpp"
#include "preprocess/cli/commands.hpp"
#include "preprocess/geometry_image_build.hpp"

namespace gfield {

namespace {

struct ImageArguments {
  std::string mesh, part, output, json;
  std::string size = "auto";
  double max_image_error = kDefaultMaxMeanError;
  size_t proxy_above = kDefaultProxyAbove;
  std::string method = "auto", components = "all", holes = "all-but-longest", protrusions = "split";
  bool no_measure = false;
  bool allow_outside_paths = false;
};

/// The options of `gfield image`, bound to `args`.
void add_image_options(CLI::App* cmd, const std::shared_ptr<ImageArguments>& args) {
  cmd->add_option("MESH", args->mesh, mesh_file_help())->required();
  cmd->add_option("--mesh", args->part,
                  "glTF: the mesh NAME (or #INDEX) (default: every primitive of the file's "
                  "scene, placed by its nodes, as one mesh)");
  cmd->add_option("-o,--output", args->output, "output geometry image (NAME.gimage.exr)")
      ->required();
  add_image_size_options(cmd, args->size, args->max_image_error, args->proxy_above);
  cmd->add_option("--method", args->method,
                  "auto: orbifold for closed genus-0 components, a disk chart otherwise;\n"
                  "orbifold: only closed genus 0; square: every component cut to a disk")
      ->check(CLI::IsMember({"auto", "orbifold", "square"}))
      ->capture_default_str();
  cmd->add_option("--components", args->components,
                  "all: one chart per component, packed; largest: keep the largest (by faces)")
      ->check(CLI::IsMember({"all", "largest"}))
      ->capture_default_str();
  cmd->add_option("--holes", args->holes,
                  "hole filling: all-but-longest (the longest loop of a component stays the\n"
                  "chart border), all, none")
      ->check(CLI::IsMember({"all-but-longest", "all", "none"}))
      ->capture_default_str();
  cmd->add_option("--protrusions", args->protrusions,
                  "split: regions a conformal map compresses below 1/10 of the mean texel\n"
                  "density (ears, legs, spouts) get charts of their own; keep: one chart per\n"
                  "component")
      ->check(CLI::IsMember({"split", "keep"}))
      ->capture_default_str();
  cmd->add_option("--json", args->json, "also write the report as JSON to this file");
  cmd->add_flag("--no-measure", args->no_measure,
                "skip distortion and reconstruction error (faster; --size auto still measures\n"
                "the mesh -> image distance it chooses by)");
  add_outside_paths_option(cmd, args->allow_outside_paths);
}

/// GeometryImageOptions from the command line's words.
GeometryImageOptions image_options(const ImageArguments& args) {
  GeometryImageOptions options;
  image_size_from_text(args.size, options.size);  // checked by --size's validator
  options.max_mean_error = args.max_image_error;
  options.proxy_above = args.proxy_above;
  options.method = args.method == "orbifold" ? ParameterizationMethod::kOrbifold
                   : args.method == "square" ? ParameterizationMethod::kSquare
                                             : ParameterizationMethod::kAuto;
  options.components =
      args.components == "largest" ? ComponentSelection::kLargest : ComponentSelection::kAll;
  options.holes = args.holes == "all"    ? HoleFilling::kAll
                  : args.holes == "none" ? HoleFilling::kNone
                                         : HoleFilling::kAllButLongest;
  options.measure = !args.no_measure;
  options.split_protrusions = args.protrusions == "split";
  return options;
}

void run_image(const ImageArguments& args) {
  TriangleMesh mesh;
  MeshAppearance appearance;
  std::vector<std::string> warnings;
  std::string error;
  const OutsidePaths outside = outside_paths(args.allow_outside_paths);
  if (!load_mesh(MeshSource{args.mesh, args.part, outside}, mesh, &appearance, warnings, error))
    throw CommandError(error);
  print_warnings(warnings);

  const GeometryImageOptions options = image_options(args);

  GeometryImage image;
  ParameterizedMesh parameterized;
  GeometryImageReport report;
  if (!build_geometry_image(mesh, options, image, parameterized, report, error, &appearance))
    throw CommandError(args.mesh + ": " + error);
  image.source = std::filesystem::path(args.mesh).filename().string();
  BuildInputs inputs;
  nlohmann::json hashed = image_options_to_json(options);
  if (!args.part.empty())
    hashed["mesh"] = printable(args.part);
  if (!hash_build_inputs(args.mesh, hashed, outside, inputs, error))
    throw CommandError(error);
  image.build_id = inputs.build_id;
  parameterized.build_id = inputs.build_id;

  const std::string obj = parameterized_mesh_path(args.output);
  if (!save_parameterized_mesh(obj, parameterized, error))
    throw CommandError(error);
  if (!save_geometry_image(args.output, image, ExrPrecision::kFloat, error))
    throw CommandError(error);

  std::printf("mesh: %s\nimage: %s (%dx%d), uv mesh: %s\n%s", printable(args.mesh).c_str(),
              printable(args.output).c_str(), image.size, image.size, printable(obj).c_str(),
              geometry_image_report_to_text(report).c_str());
  if (!args.json.empty()) {
    nlohmann::json j = geometry_image_report_to_json(report);
    j["mesh"] = printable(args.mesh);
    j["image"] = printable(args.output);
    j["parameterized_mesh"] = printable(obj);
    j["size"] = image.size;
    j["box"] = {{"min", {image.box.min.x, image.box.min.y, image.box.min.z}},
                {"max", {image.box.max.x, image.box.max.y, image.box.max.z}}};
    if (!write_text_file(args.json, j.dump(2) + "\n", error))
      throw CommandError(error);
  }
}

}  // namespace

void add_image_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "image",
      "Build the geometry image of a mesh: repair, conformal parameterisation (orbifold for "
      "closed\n"
      "genus 0, cut graph + conformal disk otherwise, one chart per component), resampling at\n"
      "texel centres. Writes OUT (.gimage.exr) and, beside it, the parameterised mesh\n"
      "(.gimage.obj: v, vt = image uv, f v/vt). Prints the report (route, times, uv faults,\n"
      "coverage, distortion, reconstruction error).");
  auto args = std::make_shared<ImageArguments>();
  add_image_options(cmd, args);
  cmd->callback([args] { run_image(*args); });
}

}  // namespace gfield
