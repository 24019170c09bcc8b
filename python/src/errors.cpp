// gfield.Error, gfield.GfieldWarning and the argument helpers of bindings.hpp.

#include "gfield/printable.hpp"
#include "python/src/bindings.hpp"

namespace gfield::python {
namespace {

/// gfield.GfieldWarning, made by bind_errors (owned by the module).
PyObject* warning_category = nullptr;

/// "shape (5, 2)" of an array, else the type of `values`.
std::string describe(const py::object& values) {
  if (py::isinstance<py::array>(values)) {
    return "shape " + py::str(values.attr("shape")).cast<std::string>();
  }
  return py::str(py::type::of(values).attr("__name__")).cast<std::string>();
}

}  // namespace

Error::Error(const std::string& message) : std::runtime_error(printable(message)) {}

void warn(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) {
    if (PyErr_WarnEx(warning_category, printable(w).c_str(), 2) != 0) {
      throw py::error_already_set();
    }
  }
}

py::array_t<float, py::array::c_style> float_rows(const py::object& values, const char* name,
                                                  py::ssize_t columns) {
  auto rows = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!rows || rows.ndim() != 2 || rows.shape(1) != columns) {
    throw py::value_error(std::string(name) + ": expected an array of shape (R, " +
                          std::to_string(columns) + "), got " +
                          (rows ? describe(rows) : describe(values)));
  }
  return rows;
}

void bind_errors(py::module_& m) {
  py::register_exception<Error>(m, "Error", PyExc_Exception);
  m.attr("Error").attr("__doc__") =
      "Bad input or a failed command: the one-line message the gfield CLI prints after\n"
      "'gfield: error: ' (the file, and the line, key or element, then the problem).";
  warning_category = PyErr_NewExceptionWithDoc(
      "gfield.GfieldWarning",
      "What gfield went on past (a missing texture: mid-grey, ...), as the CLI's\n"
      "'gfield: warning: ' lines.",
      PyExc_UserWarning, nullptr);
  if (warning_category == nullptr) {
    throw py::error_already_set();
  }
  m.attr("GfieldWarning") = py::reinterpret_steal<py::object>(warning_category);
}

}  // namespace gfield::python
