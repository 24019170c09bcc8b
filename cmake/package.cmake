# `cpack -G DEB` in the build folder: gfield_<version>_amd64.deb, installed under /usr. Depends are
# the shared libraries' packages (dpkg-shlibdeps, from dpkg-dev) plus what the binaries open at run
# time: libEGL/libGL through libepoxy and Mesa's drivers for headless rendering without a GPU.
# With the Python module (cmake/python.cmake) also python3-gfield_<version>_amd64.deb, the module
# alone (install component "python") under /usr/lib/python3/dist-packages: a user of the tools
# needs no Python, one of the module none of the tools. scripts/check-deb.sh builds and inspects
# them.
set(CPACK_PACKAGE_NAME gfield)
set(CPACK_PACKAGE_VENDOR "gfield developers")
set(CPACK_PACKAGE_CONTACT "gfield developers <gfield@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Real-time reflection and refraction from precomputed geometry fields")
set(CPACK_PACKAGE_DESCRIPTION
  "gfield builds geometry images and geometry fields of triangle meshes (CGAL, Embree) and \
renders mirror inter-reflections and refractions through them with OpenGL (gfield-view), \
with an Embree reference ray tracer (gfield render). Includes the core library \
(find_package(gfield)), the GLSL lookup library, example scenes and meshes.")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl1, libgl1, libgl1-mesa-dri")
# gfield::core's consumers compile against these headers (see cmake/gfieldConfig.cmake.in).
set(CPACK_DEBIAN_PACKAGE_SUGGESTS
  "cmake, libglm-dev, nlohmann-json3-dev, libopenexr-dev, libtbb-dev, libstb-dev")
if(GFIELD_BUILD_PYTHON)
  set(CPACK_DEB_COMPONENT_INSTALL ON)
  set(CPACK_COMPONENTS_ALL gfield python)
  set(CPACK_DEBIAN_GFIELD_PACKAGE_NAME gfield)
  set(CPACK_COMPONENT_GFIELD_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION_SUMMARY}\n${CPACK_PACKAGE_DESCRIPTION}")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-gfield)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_COMPONENT_PYTHON_DESCRIPTION
    "Python module gfield: geometry images and geometry fields on numpy arrays\n\
The gfield toolchain from Python 3 (import gfield): build the assets of a mesh, load geometry \
images and fields as numpy arrays, look rays up in a field on every core, render scenes with the \
Embree reference tracer and compare pictures.")
  # The module is built for this Python's ABI (cpython-311: python3 3.11.x); numpy for its arrays.
  math(EXPR _next_minor "${Python3_VERSION_MINOR} + 1")
  set(_python "${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "python3 (>= ${_python}), \
python3 (<< ${Python3_VERSION_MAJOR}.${_next_minor}), python3-numpy")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SUGGESTS "python3-matplotlib")
else()
  file(REMOVE ${CMAKE_BINARY_DIR}/gfield-shipped-python.txt)
endif()
include(CPack)
