# What `cmake --install build --prefix P` puts under P (docs/install.md):
#   bin/gfield, bin/gfield-view
#   share/gfield/shaders/   the GLSL files (gfield-view finds them at ../share/gfield/shaders)
#   share/gfield/web/player/  the web player that gfield-view --export-web copies (beside shaders/)
#   share/gfield/web/node_modules/  three.js's core and three-mesh-bvh for an export's vendor/
#   share/gfield/scenes/    the example scenes; share/gfield/meshes/ the bundled meshes (listed
#                           below, file by file); share/gfield/.gfield-root makes share/gfield
#                           the example scenes' root (docs/scenes.md, "Confined paths")
#   include/gfield/, lib/libgfield_core.a, lib/cmake/gfield/   gfield::core for find_package
include(CMakePackageConfigHelpers)

set(GFIELD_INSTALL_SHARE_DIR ${CMAKE_INSTALL_DATADIR}/gfield)
set(GFIELD_INSTALL_SHADER_DIR ${GFIELD_INSTALL_SHARE_DIR}/shaders)
set(GFIELD_INSTALL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/gfield)

install(DIRECTORY shaders/ DESTINATION ${GFIELD_INSTALL_SHADER_DIR}
  FILES_MATCHING PATTERN "*.glsl" PATTERN "*.vert" PATTERN "*.frag" PATTERN "*.comp")
install(FILES web/player/index.html web/player/gfield-player.js web/player/gfield-three-mesh-bvh.js
  DESTINATION ${GFIELD_INSTALL_SHARE_DIR}/web/player)
# The npm files an export's vendor/ holds (runtime/web_export.cpp, kVendorFiles: the page's
# three-mesh-bvh method), where scripts/install-web-deps.sh put them before configuring; without
# them exports offer the field and gfield's BVH alone. gfield-web-vendor.txt in the build folder
# lists those installed, under the prefix, for scripts/check-deb.sh.
set(vendor_installed "")
foreach(file three/build/three.core.js three/LICENSE three-mesh-bvh/build/index.module.js
             three-mesh-bvh/LICENSE three-mesh-bvh/package.json)
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/web/node_modules/${file})
    get_filename_component(folder ${file} DIRECTORY)
    install(FILES web/node_modules/${file}
      DESTINATION ${GFIELD_INSTALL_SHARE_DIR}/web/node_modules/${folder})
    string(APPEND vendor_installed "${GFIELD_INSTALL_SHARE_DIR}/web/node_modules/${file}\n")
  endif()
endforeach()
file(WRITE ${CMAKE_BINARY_DIR}/gfield-web-vendor.txt "${vendor_installed}")
# The example scenes and bundled meshes (with the material libraries and textures of the
# textured ones and their sources), named one by one: reports, assets and pictures that commands
# leave beside them (gfield-view builds a glTF scene's assets beside it) are never installed.
# gfield-shipped-data.txt in the build folder lists them under the prefix: scripts/check-deb.sh
# checks the package against it, and that it names every file git tracks in data/scenes and
# data/meshes (and data/.gfield-root), so a new scene or mesh cannot be left out unnoticed.
set(GFIELD_SHIPPED_SCENES
  davis-wyman-color-chart.json hurley-water-glass.json mirror-torus-instances.json
  mukai-hollow-cylinder.json mukai-plate-tilt05-w02.json mukai-plate-tilt05-w10.json
  mukai-plate-tilt30-w02.json mukai-plate-tilt30-w10.json textured-mirror.glb
  textured-mirror.json two-mirror-spheres.json)
set(GFIELD_SHIPPED_MESHES
  SOURCES.md alligator.obj beetle.obj cow.obj fandisk.obj homer.obj rocker-arm.obj
  spot-painted.mtl spot-painted.obj spot-painted.png spot.obj stanford-bunny.obj suzanne.obj
  teapot.obj torus.obj woody.obj)
set(shipped_data "")
foreach(kind scenes meshes)
  string(TOUPPER ${kind} KIND)
  set(files "")
  foreach(name IN LISTS GFIELD_SHIPPED_${KIND})
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/data/${kind}/${name})
      message(FATAL_ERROR "cmake/install.cmake ships data/${kind}/${name}, which does not exist")
    endif()
    list(APPEND files data/${kind}/${name})
    string(APPEND shipped_data "${GFIELD_INSTALL_SHARE_DIR}/${kind}/${name}\n")
  endforeach()
  install(FILES ${files} DESTINATION ${GFIELD_INSTALL_SHARE_DIR}/${kind})
endforeach()
install(FILES data/.gfield-root DESTINATION ${GFIELD_INSTALL_SHARE_DIR})
string(APPEND shipped_data "${GFIELD_INSTALL_SHARE_DIR}/.gfield-root\n")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/gfield-shipped-data.txt "${shipped_data}")

install(EXPORT gfieldTargets NAMESPACE gfield:: DESTINATION ${GFIELD_INSTALL_CMAKE_DIR})
configure_package_config_file(cmake/gfieldConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/gfieldConfig.cmake
  INSTALL_DESTINATION ${GFIELD_INSTALL_CMAKE_DIR}
  PATH_VARS GFIELD_INSTALL_SHADER_DIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/gfieldConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/gfieldConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/gfieldConfigVersion.cmake DESTINATION ${GFIELD_INSTALL_CMAKE_DIR})
