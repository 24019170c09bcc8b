#pragma once
// The Python module gfield (docs/python.md): one file per part of the toolchain, each adding its
// functions and classes to the module. Shared here: errors and warnings, paths, numpy arrays.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "gfield/geometry_image.hpp"

namespace gfield::python {

namespace py = pybind11;

/// gfield.Error: bad input or a failed command. Carries the CLI's one-line message ("FILE:
/// problem"), made printable (gfield/printable.hpp).
struct Error : std::runtime_error {
  explicit Error(const std::string& message);
};

/// Issues each of `warnings` as a gfield.GfieldWarning (warnings.warn; the GIL must be held).
void warn(const std::vector<std::string>& warnings);

/// A path argument (str or os.PathLike, through os.fspath: any bytes the file system allows) as
/// the C++ readers take it.
inline std::string path_text(const std::filesystem::path& path) {
  return path.string();
}

/// An (R, columns) C-contiguous float32 array from any array-like of that shape (converted and
/// copied when needed). Raises ValueError naming `name` for another shape.
py::array_t<float, py::array::c_style> float_rows(const py::object& values, const char* name,
                                                  py::ssize_t columns);

/// A read-only numpy array of `shape` (C order) viewing the values at `data`, which `owner` keeps
/// alive.
template <class T>
py::array read_only_view(const T* data, std::vector<py::ssize_t> shape, const py::object& owner) {
  py::array view(py::dtype::of<T>(), std::move(shape), data, owner);
  py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return view;
}

/// The (2, 3) float32 array [box.min, box.max].
py::array_t<float> box_to_python(const Box& box);
/// Reads a geometry image file (GIL released); raises Error.
std::shared_ptr<GeometryImage> load_geometry_image_file(const std::filesystem::path& path);

void bind_errors(py::module_& m);
void bind_mesh(py::module_& m);
void bind_build(py::module_& m);
void bind_geometry_image(py::module_& m);
void bind_geometry_field(py::module_& m);
void bind_render(py::module_& m);
void bind_scene(py::module_& m);

}  // namespace gfield::python
