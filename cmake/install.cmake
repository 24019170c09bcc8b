# What `cmake --install build --prefix P` puts under P (docs/install.md):
#   bin/gfield, bin/gfield-view
#   share/gfield/shaders/   the GLSL files (gfield-view finds them at ../share/gfield/shaders)
#   share/gfield/scenes/    the example scenes; share/gfield/meshes/ the bundled meshes
#   include/gfield/, lib/libgfield_core.a, lib/cmake/gfield/   gfield::core for find_package
include(CMakePackageConfigHelpers)

set(GFIELD_INSTALL_SHARE_DIR ${CMAKE_INSTALL_DATADIR}/gfield)
set(GFIELD_INSTALL_SHADER_DIR ${GFIELD_INSTALL_SHARE_DIR}/shaders)
set(GFIELD_INSTALL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/gfield)

install(DIRECTORY shaders/ DESTINATION ${GFIELD_INSTALL_SHADER_DIR}
  FILES_MATCHING PATTERN "*.glsl" PATTERN "*.vert" PATTERN "*.frag")
install(DIRECTORY data/scenes/ DESTINATION ${GFIELD_INSTALL_SHARE_DIR}/scenes
  FILES_MATCHING PATTERN "*.json" PATTERN "*.glb")
# The meshes (with the material libraries and textures of the textured ones) and their sources
# only: assets that scripts/demo.sh built beside them stay behind.
install(DIRECTORY data/meshes/ DESTINATION ${GFIELD_INSTALL_SHARE_DIR}/meshes
  FILES_MATCHING PATTERN "*.obj" PATTERN "*.mtl" PATTERN "*.png" PATTERN "SOURCES.md"
  PATTERN "*.gimage.obj" EXCLUDE)

install(EXPORT gfieldTargets NAMESPACE gfield:: DESTINATION ${GFIELD_INSTALL_CMAKE_DIR})
configure_package_config_file(cmake/gfieldConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/gfieldConfig.cmake
  INSTALL_DESTINATION ${GFIELD_INSTALL_CMAKE_DIR}
  PATH_VARS GFIELD_INSTALL_SHADER_DIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/gfieldConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/gfieldConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/gfieldConfigVersion.cmake DESTINATION ${GFIELD_INSTALL_CMAKE_DIR})
