#include "preprocess/asset_build.hpp"

#include <cstdio>
#include <filesystem>
#include <new>

#include "geometry/parameterized_mesh.hpp"
#include "gfield/atomic_file.hpp"
#include "gfield/gpu_storage.hpp"
#include "gfield/printable.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/asset_files.hpp"
#include "preprocess/asset_staging.hpp"
#include "preprocess/topology.hpp"
#include "preprocess/verify.hpp"

namespace gfield {
namespace {

/// The report's figures of the field built (its layout at `format`).
void describe_field(const GeometryField& field, const FieldFileFormat& format,
                    FieldFileReport& report) {
  report.format = format.version;
  report.table_lines = 0;  // the line table's lines: 1 hit, or 3 and more (two rays each)
  for (size_t k = 0; k < report.build.lines_by_hits.size(); ++k) {
    if (k == 1 || k >= 3) {
      report.table_lines += report.build.lines_by_hits[k] / 2;
    }
  }
  report.line_words = field.lines.size();
  report.interior_hits = field.interior.size();
  const int bits[3] = {8, 16, 32};
  if (format.version == kFieldFormatVersion) {
    report.layers = field.layers;
    for (int b = 0; b < 3; ++b) {
      report.gpu_bytes[size_t(b)] = field_gpu_bytes(field, bits[b]);
    }
  } else {
    report.layers = layered_field_layers(report.build, format.layers);
    for (int b = 0; b < 3; ++b) {
      report.gpu_bytes[size_t(b)] =
          layered_field_gpu_bytes(field.samples_per_side, report.layers, bits[b]);
    }
  }
}

}  // namespace

bool write_field_file(const GeometryImage& image, const ParameterizedMesh& pm, int samples_per_side,
                      const FieldFileFormat& format, const std::string& output,
                      FieldFileReport& report, std::string& error, const JobControl* control) {
  report.samples_per_side = samples_per_side;
  report.image_size = image.size;
  const bool half = format.precision == ExrPrecision::kHalf;
  report.memory_estimate = field_memory_estimate(samples_per_side, half);
  if (!check_field_size(samples_per_side, half, error)) {
    error = output + ": " + error;
    return false;
  }
  Stopwatch watch;
  EmbreeMesh embree;
  if (!embree.build(pm.mesh, error)) {
    error = output + ": " + error;
    return false;
  }
  report.bvh_seconds = watch.seconds();
  GeometryField field;
  if (!build_geometry_field(pm, embree, image, samples_per_side, field, error, &report.build,
                            control)) {
    error = output + ": " + error;
    return false;
  }
  field.source = image.source;
  field.build_id = image.build_id;
  describe_field(field, format, report);
  watch.restart();
  report_progress(control, "write", 0.0);
  const bool written =
      format.version == kFieldFormatVersion
          ? save_geometry_field(output, field, format.precision, error)
          : save_layered_geometry_field(output, field, report.layers, format.precision, error);
  if (!written) {
    return false;
  }
  report.write_seconds = watch.seconds();
  report_progress(control, "write", 1.0);
  std::error_code ec;
  report.file_bytes = size_t(std::filesystem::file_size(output, ec));
  return true;
}

nlohmann::json image_options_to_json(const GeometryImageOptions& o) {
  const char* methods[] = {"auto", "orbifold", "square"};
  const char* holes[] = {"all-but-longest", "all", "none"};
  const bool automatic = o.size == kAutoImageSize;
  return {{"size", automatic ? nlohmann::json("auto") : nlohmann::json(o.size)},
          {"max_mean_error_percent",
           automatic ? nlohmann::json(o.max_mean_error) : nlohmann::json(nullptr)},
          {"method", methods[int(o.method)]},
          {"components", o.components == ComponentSelection::kLargest ? "largest" : "all"},
          {"holes", holes[int(o.holes)]},
          {"gutter", o.gutter},
          {"split_protrusions", o.split_protrusions},
          {"max_split_depth", o.max_split_depth},
          {"measure", o.measure},
          {"error_samples", o.error_samples},
          {"seed", o.seed},
          {"proxy_above", o.proxy_above}};
}

nlohmann::json asset_options_to_json(const AssetOptions& o) {
  nlohmann::json options = {
      {"image", image_options_to_json(o.image)},
      {"samples_per_side", o.samples_per_side},
      {"field_format", o.field.version},
      {"field_precision", o.field.precision == ExrPrecision::kHalf ? "half" : "float"},
      {"verify_rays", o.verify_rays}};
  if (o.field.version != kFieldFormatVersion) {
    options["field_layers"] =
        o.field.layers == kAutoLayers ? nlohmann::json("auto") : nlohmann::json(o.field.layers);
  }
  if (!o.part.empty()) {
    options["mesh"] = printable(o.part);
  }
  return options;
}

bool asset_build_inputs(const std::string& mesh_path, const AssetOptions& options,
                        BuildInputs& inputs, std::string& error) {
  return hash_build_inputs(mesh_path, asset_options_to_json(options), options.outside_paths, inputs,
                           error);
}

namespace {

/// The geometry image (with the albedo of `appearance`) and its parameterised mesh of `mesh` into
/// the staged files.
bool write_image_files(const TriangleMesh& mesh, const MeshAppearance& appearance,
                       const std::string& mesh_path, const AssetOptions& options,
                       const std::string& build_id, const AssetFiles& staged, GeometryImage& image,
                       ParameterizedMesh& pm, AssetReport& report, std::string& error) {
  if (!build_geometry_image(mesh, options.image, image, pm, report.geometry_image, error,
                            &appearance)) {
    error = mesh_path + ": " + error;
    return false;
  }
  image.source = std::filesystem::path(mesh_path).filename().string();
  image.build_id = build_id;
  pm.build_id = build_id;
  Stopwatch watch;
  if (!save_parameterized_mesh(staged.parameterized_mesh, pm, error) ||
      !save_geometry_image(staged.image, image, ExrPrecision::kFloat, error)) {
    return false;
  }
  report.image_size = image.size;
  report.image_write_seconds = watch.seconds();
  report.box = image.box;
  return true;
}

/// True, with the error "MESH: interrupted", when `control` asks the build to stop.
bool interrupted(const JobControl* control, const std::string& mesh_path, std::string& error) {
  if (!stop_requested(control)) {
    return false;
  }
  error = mesh_path + ": " + kInterrupted;
  return true;
}

/// `error` with the build folder's file names replaced by the asset's (a full disk names the
/// file the user asked for, not where it was being written).
std::string with_asset_names(std::string error, const AssetFiles& staged, const AssetFiles& files) {
  const std::pair<const std::string*, const std::string*> names[] = {
      {&staged.parameterized_mesh, &files.parameterized_mesh},
      {&staged.image, &files.image},
      {&staged.field, &files.field},
      {&staged.report, &files.report}};
  for (const auto& [from, to] : names) {
    for (size_t at = error.find(*from); at != std::string::npos;
         at = error.find(*from, at + to->size())) {
      error.replace(at, from->size(), *to);
    }
  }
  return error;
}

/// The error of a build that ran out of memory: the mesh, the stage it was in ("building the
/// geometry image", ...) and what a build of its size needs, measured.
std::string out_of_memory_message(const std::string& mesh_path, const TriangleMesh& mesh,
                                  const char* stage) {
  // Peak resident memory of whole builds without a proxy: the Stanford bunny midpoint-subdivided
  // to 278K and 1.1M faces (docs/geometry-image.md, "Bad input").
  constexpr double kBytesPerFace = 2048.0;
  char needed[64];
  std::snprintf(needed, sizeof(needed), "%.1f GB",
                kBytesPerFace * double(mesh.triangles.size()) / 1e9);
  return mesh_path + ": out of memory while " + stage + " (a build of its " +
         std::to_string(mesh.triangles.size()) + " triangles needs about " + needed +
         "; nothing was written)";
}

/// Writes the asset's four files into `staged` (the build folder): the parts of build_asset
/// after the mesh is read. `stage` names the stage under way (for out_of_memory_message).
bool write_asset_files(const TriangleMesh& mesh, const MeshAppearance& appearance,
                       const std::string& mesh_path, const std::string& name,
                       const AssetOptions& options, const AssetFiles& staged, AssetReport& report,
                       const char*& stage, std::string& error) {
  GeometryImage image;
  ParameterizedMesh pm;
  stage = "building the geometry image";
  report_progress(options.control, "image", 0.0);
  if (!write_image_files(mesh, appearance, mesh_path, options, report.build_id, staged, image, pm,
                         report, error) ||
      interrupted(options.control, mesh_path, error)) {
    return false;
  }
  report_progress(options.control, "image", 1.0);
  stage = "casting the geometry field";
  if (!write_field_file(image, pm, options.samples_per_side, options.field, staged.field,
                        report.geometry_field, error, options.control) ||
      interrupted(options.control, mesh_path, error)) {
    return false;
  }
  report.field_precision = options.field.precision;
  stage = "verifying the asset";
  Stopwatch verify_watch;
  if (options.verify_rays > 0) {
    VerifyOptions verify;
    verify.rays = options.verify_rays;
    verify.original = mesh_path;
    verify.original_part = options.part;
    verify.original_outside_paths = options.outside_paths;
    verify.proxy = report.geometry_image.proxy.used;
    report_progress(options.control, "verify", 0.0);
    if (!verify_asset_files(staged, name, verify, report.accuracy.emplace(), error) ||
        interrupted(options.control, mesh_path, error)) {
      return false;
    }
    report_progress(options.control, "verify", 1.0);
  }
  const AssetFiles files = asset_files(name);
  report.files = {printable(files.image), printable(files.parameterized_mesh),
                  printable(files.field), ""};
  std::error_code ec;
  report.image_file_bytes = size_t(std::filesystem::file_size(staged.image, ec));
  const FieldFileReport& field = report.geometry_field;
  report.stage_seconds.image = report.geometry_image.seconds.total;
  report.stage_seconds.image_write = report.image_write_seconds;
  report.stage_seconds.field = field.bvh_seconds + field.build.seconds;
  report.stage_seconds.field_write = field.write_seconds;
  report.stage_seconds.verify = options.verify_rays > 0 ? verify_watch.seconds() : 0.0;
  return true;
}

/// The report's record of the mesh read and of the build's inputs.
AssetReport begin_report(const std::string& mesh_path, const TriangleMesh& mesh,
                         const std::vector<std::string>& warnings, const AssetOptions& options,
                         const BuildInputs& inputs) {
  AssetReport report;
  report.mesh = printable(std::filesystem::path(mesh_path).filename().string());
  report.source_path = printable(std::filesystem::absolute(mesh_path).string());
  report.build_id = inputs.build_id;
  report.inputs = inputs.record;
  report.mesh_modified_ns = inputs.mesh_modified_ns;
  report.mesh_part = printable(options.part);
  for (const std::string& w : warnings) {
    report.warnings.push_back(printable(w));
  }
  report.topology = analyze_topology(mesh);
  return report;
}

}  // namespace

bool build_asset(const std::string& mesh_path, const std::string& name, const AssetOptions& options,
                 const BuildInputs& inputs, AssetReport& report, std::string& error) {
  Stopwatch watch;
  if (options.field.version != kFieldFormatVersion &&
      (options.field.version != kLayeredFieldVersion || options.field.layers < kAutoLayers ||
       options.field.layers > kMaxFieldLayers)) {
    error = "field format " + std::to_string(options.field.version) + " with " +
            std::to_string(options.field.layers) + " layers: expected format 3, or 2 with 1 to " +
            std::to_string(kMaxFieldLayers) + " layers";
    return false;
  }
  if (!check_field_size(options.samples_per_side, true, error)) {
    return false;
  }
  TriangleMesh mesh;
  MeshAppearance appearance;
  std::vector<std::string> warnings;
  report_progress(options.control, "mesh", 0.0);
  const Stopwatch mesh_watch;
  bool loaded = false;
  try {
    loaded = load_mesh(MeshSource{mesh_path, options.part, options.outside_paths}, mesh,
                       &appearance, warnings, error);
  } catch (const std::bad_alloc&) {
    std::error_code ec;
    error = mesh_path + ": out of memory while reading it (" +
            std::to_string(std::filesystem::file_size(mesh_path, ec)) + " bytes)";
  }
  if (!loaded || interrupted(options.control, mesh_path, error)) {
    return false;
  }
  report_progress(options.control, "mesh", 1.0);
  const double mesh_seconds = mesh_watch.seconds();
  AssetStaging staging;
  if (!staging.open(name, error)) {
    return false;
  }
  report = begin_report(mesh_path, mesh, warnings, options, inputs);
  report.stage_seconds.mesh = mesh_seconds;
  bool written = false;
  const char* stage = "building the geometry image";
  try {
    written = write_asset_files(mesh, appearance, mesh_path, name, options, staging.staged(),
                                report, stage, error);
  } catch (const std::bad_alloc&) {
    error = out_of_memory_message(mesh_path, mesh, stage);
  }
  if (written) {
    report.seconds = watch.seconds();
    written = write_text_file(staging.staged().report, asset_report_to_json(report).dump(2) + "\n",
                              error);
  }
  if (!written || !staging.publish(error)) {
    error = with_asset_names(error, staging.staged(), asset_files(name));
    return false;
  }
  return true;
}

bool build_asset_at(const std::string& mesh_path, const std::string& name,
                    const AssetOptions& options, AssetReport& report, size_t& stale_removed,
                    std::string& error) {
  const std::string file = std::filesystem::path(name).filename().string();
  if (file.empty() || file[0] == '.') {
    error = name + ": expected DIR/NAME, the name the asset's files begin with (NAME.gimage.exr, " +
            "...): not a folder, and not beginning with '.'";
    return false;
  }
  BuildInputs inputs;
  if (!asset_build_inputs(mesh_path, options, inputs, error)) {
    return false;
  }
  const std::filesystem::path dir = std::filesystem::path(name).parent_path();
  std::error_code ec;
  if (!dir.empty()) {
    std::filesystem::create_directories(dir, ec);
  }
  stale_removed = remove_stale_staging(dir.empty() ? "." : dir.string());
  return build_asset(mesh_path, name, options, inputs, report, error);
}

}  // namespace gfield
