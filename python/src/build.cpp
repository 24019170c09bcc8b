// gfield.build: `gfield build MESH -o OUT` from Python, with the same options, a progress
// callback and Ctrl-C.

#include <string>

#include "preprocess/asset_arguments.hpp"
#include "preprocess/thread_limit.hpp"
#include "python/src/bindings.hpp"
#include "python/src/interruptible.hpp"
#include "python/src/json_object.hpp"

namespace gfield::python {
namespace {

/// `value` as the text of `gfield build --size` ("auto", or an integer's digits).
std::string size_text(const py::object& value) {
  if (py::isinstance<py::str>(value)) {
    return value.cast<std::string>();
  }
  if (py::isinstance<py::int_>(value) && !py::isinstance<py::bool_>(value)) {
    return py::str(value).cast<std::string>();
  }
  return py::repr(value).cast<std::string>();
}

/// --layers: "auto" (kAutoLayers) or 1..kMaxFieldLayers.
int layers_value(const py::object& value) {
  if (py::isinstance<py::str>(value) && value.cast<std::string>() == "auto") {
    return kAutoLayers;
  }
  if (py::isinstance<py::int_>(value) && !py::isinstance<py::bool_>(value)) {
    const long long layers = value.cast<long long>();
    if (layers >= 1 && layers <= kMaxFieldLayers) {
      return int(layers);
    }
  }
  throw py::value_error("layers: expected auto or 1 to " + std::to_string(kMaxFieldLayers) +
                        ", got " + py::repr(value).cast<std::string>());
}

/// Raises ValueError "NAME: expected ONE or OTHER..., got VALUE" unless `value` is in `choices`.
void check_choice(const char* name, const std::string& value,
                  std::initializer_list<const char*> choices) {
  std::string expected;
  for (const char* choice : choices) {
    if (value == choice) {
      return;
    }
    expected += std::string(expected.empty() ? "" : ", ") + choice;
  }
  throw py::value_error(std::string(name) + ": expected one of " + expected + ", got " + value);
}

py::object build(const std::filesystem::path& mesh_path, const std::filesystem::path& out,
                 const std::string& part, const py::object& size, double max_image_error,
                 long long proxy_above, int samples, int format, const py::object& layers,
                 const std::string& precision, long long verify_rays, const std::string& method,
                 const std::string& components, bool allow_outside_paths, int threads,
                 const py::object& progress) {
  AssetArguments args;
  args.size = size_text(size);
  if (const std::string problem = image_size_problem(args.size); !problem.empty()) {
    throw py::value_error("size: " + problem);
  }
  args.max_image_error = max_image_error;
  if (const std::string problem = max_image_error_problem(
          max_image_error, py::repr(py::float_(max_image_error)).cast<std::string>());
      !problem.empty()) {
    throw py::value_error("max_image_error: " + problem);
  }
  if (proxy_above < 0) {
    throw py::value_error("proxy_above: expected 0 (never) or more, got " +
                          std::to_string(proxy_above));
  }
  args.proxy_above = size_t(proxy_above);
  args.samples = samples;
  if (format != kFieldFormatVersion && format != kLayeredFieldVersion) {
    throw py::value_error("format: expected 3 or 2, got " + std::to_string(format));
  }
  args.format = format;
  args.layers = layers_value(layers);
  check_choice("precision", precision, {"half", "float"});
  args.full = precision == "float";
  if (verify_rays < 0) {
    throw py::value_error("verify_rays: expected 0 or more, got " + std::to_string(verify_rays));
  }
  args.verify_rays = size_t(verify_rays);
  check_choice("method", method, {"auto", "orbifold", "square"});
  args.method = method;
  check_choice("components", components, {"all", "largest"});
  args.components = components;
  args.allow_outside_paths = allow_outside_paths;
  if (threads < 0 || threads > 4096) {
    throw py::value_error("threads: expected 0 (all cores) to 4096, got " +
                          std::to_string(threads));
  }
  AssetOptions options = asset_options(args);
  options.part = part;
  AssetReport report;
  std::string error;
  bool built = false;
  run_interruptible(
      [&](const JobControl& control) {
        const ThreadLimit limit(threads);
        options.control = &control;
        size_t stale = 0;
        built = build_asset_at(path_text(mesh_path), path_text(out), options, report, stale, error);
      },
      progress);
  if (!built) {
    throw Error(error);
  }
  warn(report.warnings);
  return json_to_python(asset_report_to_json(report));
}

}  // namespace

void bind_build(py::module_& m) {
  m.def("build", &build, py::arg("mesh_path"), py::arg("out"), py::kw_only(), py::arg("mesh") = "",
        py::arg("size") = "auto", py::arg("max_image_error") = kDefaultMaxMeanError,
        py::arg("proxy_above") = kDefaultProxyAbove, py::arg("samples") = 24,
        py::arg("format") = kFieldFormatVersion, py::arg("layers") = "auto",
        py::arg("precision") = "half", py::arg("verify_rays") = kDefaultVerifyRays,
        py::arg("method") = "auto", py::arg("components") = "all",
        py::arg("allow_outside_paths") = false, py::arg("threads") = 0,
        py::arg("progress") = py::none(),
        "Builds the asset OUT (DIR/NAME: NAME.gimage.exr, NAME.gimage.obj, NAME.gfield.exr,\n"
        "NAME.report.json) from a mesh file, as `gfield build MESH -o OUT` does, and returns\n"
        "the report (the dict of NAME.report.json).\n\n"
        "The options are gfield build's: mesh (--mesh, glTF), size ('auto' or texels per\n"
        "side, 8 to 8192), max_image_error (percent of the diagonal, for size='auto'),\n"
        "proxy_above (faces above which the image is charted on a simplified proxy; 0: never),\n"
        "samples (N, 4 to 48), format (3: compact, or 2: layered), layers (format 2: 'auto'\n"
        "or K, 1 to 4), precision ('half' or 'float'),\n"
        "verify_rays (per family; 0 skips the accuracy), method ('auto', 'orbifold',\n"
        "'square'), components ('all', 'largest'), allow_outside_paths, threads (0: all\n"
        "cores).\n\n"
        "progress: None, or a callable (stage: str, done: float) called on this thread with\n"
        "the stage ('mesh', 'image', 'field', 'write', 'verify') and the share of it done,\n"
        "in [0, 1], at most every 50 ms; gfield.print_progress prints a bar on stderr.\n"
        "Ctrl-C (KeyboardInterrupt), or an exception from the callback, stops the build within\n"
        "a table row of the field's casts (between stages elsewhere) and is raised once the\n"
        "build has cleaned up: the old asset at OUT, if any, is left whole.\n\n"
        "Raises ValueError for an option of the wrong form and gfield.Error with the CLI's\n"
        "one-line message for bad input or a failed build.");
}

}  // namespace gfield::python
