// gfield.render (the Embree reference tracer into a numpy picture) and gfield.compare (PSNR and
// SSIM of two pictures), as `gfield render` and `gfield compare`.

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "geometry/scene_file.hpp"
#include "gfield/camera_text.hpp"
#include "gfield/image.hpp"
#include "gfield/image_metrics.hpp"
#include "preprocess/reference_tracer.hpp"
#include "python/src/bindings.hpp"
#include "python/src/interruptible.hpp"

namespace gfield::python {
namespace {

/// The options of `gfield render` from gfield.render's arguments; ValueError for a bad one.
RenderOptions render_options(const std::optional<std::pair<int, int>>& size, int spp, int depth,
                             const std::string& dielectric, std::uint64_t seed,
                             bool strata_centres) {
  RenderOptions options;
  if (size && (size->first <= 0 || size->second <= 0)) {
    throw py::value_error("size: expected (width, height), both positive, got (" +
                          std::to_string(size->first) + ", " + std::to_string(size->second) + ")");
  }
  if (size) {
    options.width = size->first;
    options.height = size->second;
  }
  if (spp < 1) {
    throw py::value_error("spp: expected 1 or more, got " + std::to_string(spp));
  }
  if (depth < 0 || depth > 1000) {
    throw py::value_error("depth: expected 0 to 1000, got " + std::to_string(depth));
  }
  options.samples_per_pixel = spp;
  options.max_depth = depth;
  if (!parse_dielectric_mode(dielectric, options.dielectric)) {
    throw py::value_error("dielectric: expected full, refract-only or tir-only, got " + dielectric);
  }
  options.seed = seed;
  options.jitter = !strata_centres;
  return options;
}

/// The h x w x 3 float32 array of `image`.
py::array_t<float> picture_array(const Image& image) {
  py::array_t<float> array({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)});
  std::memcpy(array.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(glm::vec3));
  return array;
}

py::array_t<float> render(const std::filesystem::path& scene_path,
                          const std::optional<std::pair<int, int>>& size, int spp, int depth,
                          const std::string& dielectric, std::uint64_t seed, bool strata_centres,
                          const std::optional<std::string>& camera, bool allow_outside_paths,
                          const py::object& progress) {
  RenderOptions options = render_options(size, spp, depth, dielectric, seed, strata_centres);
  const std::string file = path_text(scene_path);
  Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  if (!load_scene_file(file, scene, warnings, error,
                       allow_outside_paths ? OutsidePaths::kAllowed : OutsidePaths::kRefused)) {
    throw Error(error);
  }
  warn(warnings);
  if (camera && !parse_camera_text(*camera, scene.camera, error)) {
    throw py::value_error("camera " + *camera + ": " + error);
  }
  const int width = options.width > 0 ? options.width : scene.width;
  const int height = options.height > 0 ? options.height : scene.height;
  if (!check_render_budget(width, height, options.samples_per_pixel, error)) {
    throw Error(file + ": " + error);
  }
  Image image;
  bool built = false;
  run_interruptible(
      [&](const JobControl& control) {
        ReferenceTracer tracer;
        built = tracer.build(scene, error);
        if (built) {
          options.control = &control;
          image = tracer.render(options);
        }
      },
      progress);
  if (!built) {
    throw Error(error);
  }
  return picture_array(image);
}

/// True for a str or an os.PathLike.
bool is_path(const py::object& value) {
  return py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__");
}

/// A picture given as an (h, w, 3) array-like or a file (EXR, HDR, PNG, JPEG: load_image);
/// `name` names it in messages.
Image picture(const py::object& value, const char* argument, std::string& name) {
  Image image;
  if (is_path(value)) {
    name = path_text(value.cast<std::filesystem::path>());
    std::string error;
    if (!load_image(name, image, error)) {
      throw Error(error);
    }
    return image;
  }
  name = argument;
  auto array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array || array.ndim() != 3 || array.shape(2) != 3) {
    throw py::value_error(std::string(argument) +
                          ": expected an array of shape (height, width, 3) or an image file");
  }
  image = Image(int(array.shape(1)), int(array.shape(0)));
  std::memcpy(image.pixels.data(), array.data(), image.pixels.size() * sizeof(glm::vec3));
  return image;
}

py::dict compare(const py::object& a, const py::object& b, const py::object& mask, bool linear) {
  std::string a_name, b_name, mask_name;
  Image first = picture(a, "a", a_name);
  Image second = picture(b, "b", b_name);
  if (first.width != second.width || first.height != second.height) {
    throw Error(b_name + ": size " + std::to_string(second.width) + "x" +
                std::to_string(second.height) + " differs from " + a_name + " (" +
                std::to_string(first.width) + "x" + std::to_string(first.height) + ")");
  }
  PixelMask pixels;
  if (is_path(mask)) {
    const Image m = picture(mask, "mask", mask_name);
    if (m.width != first.width || m.height != first.height) {
      throw Error(mask_name + ": mask size differs from the images");
    }
    pixels = mask_from_image(m);
  } else if (!mask.is_none()) {
    mask_name = "mask";
    const auto flags = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(mask);
    if (!flags || flags.ndim() != 2 || flags.shape(0) != first.height ||
        flags.shape(1) != first.width) {
      throw py::value_error(
          "mask: expected a (height, width) array of the pictures' size or an "
          "image file");
    }
    pixels.assign(flags.data(), flags.data() + flags.size());
  }
  ImageComparison c;
  MetricScale scale;
  // The files' names decide the scale (arrays are linear values); read while the GIL is held.
  const std::string a_file = is_path(a) ? a_name : "", b_file = is_path(b) ? b_name : "";
  {
    py::gil_scoped_release release;
    scale = match_metric_scale(first, a_file, second, b_file, linear);
    c = compare_images(first, second, pixels);
  }
  if (c.pixels == 0) {
    throw Error(mask_name + ": the mask selects no pixel");
  }
  py::dict result;
  result["pixels"] = c.pixels;
  result["psnr_db"] = c.psnr;
  result["ssim"] = c.ssim;
  result["mse"] = c.mse;
  result["max_abs_error"] = c.max_abs_error;
  result["mean_abs_error"] = c.mean_abs_error;
  result["scale"] = metric_scale_name(scale);
  return result;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("render", &render, py::arg("scene_path"), py::arg("size") = py::none(), py::arg("spp") = 8,
        py::arg("depth") = 10, py::kw_only(), py::arg("dielectric") = "full", py::arg("seed") = 1,
        py::arg("strata_centres") = false, py::arg("camera") = py::none(),
        py::arg("allow_outside_paths") = false, py::arg("progress") = py::none(),
        "Renders a scene with the Embree reference ray tracer, as `gfield render` does, and\n"
        "returns the picture: an (h, w, 3) float32 array of linear RGB, row 0 at the top.\n\n"
        "size: (width, height), default the scene's; spp: stratified samples per pixel;\n"
        "depth: reflections/refractions per path; dielectric: 'full', 'refract-only' or\n"
        "'tir-only'; seed: of the jitter; strata_centres: samples at the strata centres (the\n"
        "positions gfield-view samples); camera: 'EX,EY,EZ,TX,TY,TZ[,UX,UY,UZ[,FOV]]'.\n"
        "progress: None or a callable (stage 'render', share of rows done), as for build;\n"
        "Ctrl-C stops the render within a row and raises KeyboardInterrupt. Raises ValueError\n"
        "for a bad argument and gfield.Error for a bad scene or a render beyond the limits.");
  m.def("compare", &compare, py::arg("a"), py::arg("b"), py::kw_only(),
        py::arg("mask") = py::none(), py::arg("linear") = false,
        "PSNR and SSIM of two pictures, as `gfield compare A B --json`: each an (h, w, 3)\n"
        "array-like of linear values (peak 1) or an image file (EXR, HDR, PNG, JPEG). Where\n"
        "either is a PNG or JPEG file, both are compared on the values a PNG stores (sRGB, 8\n"
        "bits, as ImageMagick and scikit-image do) unless linear=True; otherwise in linear\n"
        "light. mask: None, an (h, w) bool array, or an image file whose pixels above 0.5\n"
        "count. Returns a dict: pixels, psnr_db (inf for equal pictures), ssim, mse,\n"
        "max_abs_error, mean_abs_error, scale ('display (sRGB 8-bit)' or 'linear light').\n"
        "Raises gfield.Error for unreadable files, pictures of different sizes or a mask\n"
        "that selects no pixel.");
}

}  // namespace gfield::python
