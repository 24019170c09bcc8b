// The extension module gfield._gfield, re-exported by the package gfield (python/gfield/).

#include "gfield/atomic_file.hpp"
#include "python/src/bindings.hpp"

PYBIND11_MODULE(_gfield, m) {
  namespace python = gfield::python;
  m.doc() =
      "gfield: geometry images and geometry fields of triangle meshes, their lookups, and the\n"
      "Embree reference tracer, on numpy arrays (docs/python.md).";
  // Ctrl-C stays Python's KeyboardInterrupt (gfield.build stops through its JobControl).
  gfield::leave_signals_to_host();
  m.attr("__version__") = GFIELD_VERSION;
  python::bind_errors(m);
  python::bind_mesh(m);
  python::bind_build(m);
  python::bind_geometry_image(m);
  python::bind_geometry_field(m);
  python::bind_render(m);
  python::bind_scene(m);
}
