# `cpack -G DEB` in the build folder: gfield_<version>_amd64.deb, installed under /usr. Depends are
# the shared libraries' packages (dpkg-shlibdeps, from dpkg-dev) plus what the binaries open at run
# time: libEGL/libGL through libepoxy and Mesa's drivers for headless rendering without a GPU.
# scripts/check-deb.sh builds and inspects it.
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
include(CPack)
