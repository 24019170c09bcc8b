// gfield.GeometryImage: a geometry image file's texels as numpy arrays.

#include "gfield/exr_io.hpp"
#include "gfield/printable.hpp"
#include "python/src/bindings.hpp"

namespace gfield::python {
namespace {

/// An n x n x `channels` view of the texels at `data` (row j = scanline j), kept alive by
/// `self`.
py::array texel_view(const py::object& self, const float* data, int channels) {
  const auto n = py::ssize_t(self.cast<const GeometryImage&>().size);
  if (channels == 1) {
    return read_only_view(data, {n, n}, self);
  }
  return read_only_view(data, {n, n, py::ssize_t(channels)}, self);
}

}  // namespace

py::array_t<float> box_to_python(const Box& box) {
  py::array_t<float> array({2, 3});
  for (int a = 0; a < 3; ++a) {
    array.mutable_at(0, a) = box.min[a];
    array.mutable_at(1, a) = box.max[a];
  }
  return array;
}

std::shared_ptr<GeometryImage> load_geometry_image_file(const std::filesystem::path& path) {
  auto image = std::make_shared<GeometryImage>();
  std::string error;
  bool loaded = false;
  {
    py::gil_scoped_release release;
    loaded = load_geometry_image(path_text(path), *image, error);
  }
  if (!loaded) {
    throw Error(error);
  }
  return image;
}

void bind_geometry_image(py::module_& m) {
  py::class_<GeometryImage, std::shared_ptr<GeometryImage>>(
      m, "GeometryImage",
      "A geometry image (NAME.gimage.exr, docs/formats.md): the surface resampled on an n x n\n"
      "grid of its parameter domain. Texel (i, j), column i of scanline j, is [j, i] of the\n"
      "arrays, its centre at uv ((i + 0.5) / n, (j + 0.5) / n). Arrays are read-only views.")
      .def_static("load", &load_geometry_image_file, py::arg("path"),
                  "Reads NAME.gimage.exr (format versions 1 and 2). Raises gfield.Error with the\n"
                  "reader's one-line message for a damaged or foreign file.")
      .def_property_readonly(
          "size", [](const GeometryImage& image) { return image.size; }, "n, texels per side.")
      .def_property_readonly(
          "box", [](const GeometryImage& image) { return box_to_python(image.box); },
          "(2, 3) float32: the box's min and max corners (mesh coordinates), which map to the\n"
          "unit cube of the field.")
      .def_property_readonly(
          "source", [](const GeometryImage& image) { return printable(image.source); },
          "File name of the mesh it was built from.")
      .def_property_readonly(
          "build_id", [](const GeometryImage& image) { return printable(image.build_id); },
          "The build's id ('' for files without one).")
      .def_property_readonly(
          "ray_offset", [](const GeometryImage& image) { return image.ray_offset; },
          "How far off the surface a ray leaving it starts, in box diagonals.")
      .def_property_readonly(
          "positions",
          [](const py::object& self) {
            return texel_view(self, &self.cast<const GeometryImage&>().position.data()->x, 3);
          },
          "(n, n, 3) float32: surface positions, mesh coordinates.")
      .def_property_readonly(
          "normals",
          [](const py::object& self) {
            return texel_view(self, &self.cast<const GeometryImage&>().normal.data()->x, 3);
          },
          "(n, n, 3) float32: unit surface normals.")
      .def_property_readonly(
          "coverage",
          [](const py::object& self) {
            return texel_view(self, self.cast<const GeometryImage&>().coverage.data(), 1);
          },
          "(n, n) float32: 1 inside the parameterised surface, 0 in padding.")
      .def_property_readonly(
          "albedo",
          [](const py::object& self) -> py::object {
            const GeometryImage& image = self.cast<const GeometryImage&>();
            if (image.albedo.empty()) {
              return py::none();
            }
            return texel_view(self, &image.albedo.data()->x, 3);
          },
          "(n, n, 3) float32: linear RGB base colour, or None when the mesh carried none.")
      .def("__repr__", [](const GeometryImage& image) {
        return "<gfield.GeometryImage " + std::to_string(image.size) + "x" +
               std::to_string(image.size) + " of " + printable(image.source) + ">";
      });
}

}  // namespace gfield::python
