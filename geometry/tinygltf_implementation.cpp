// The one translation unit that compiles Debian's tinygltf (libtinygltf-dev ships it as a
// header-only library with a shared build; gfield compiles it itself so that the sanitizer and
// fuzz builds instrument it too). gfield decodes images itself (mesh_appearance.hpp) and writes
// glTF itself (gltf_writer.cpp): geometry/CMakeLists.txt defines TINYGLTF_NO_STB_IMAGE,
// TINYGLTF_NO_STB_IMAGE_WRITE and TINYGLTF_NO_EXTERNAL_IMAGE for every file that includes it.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
