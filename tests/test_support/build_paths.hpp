#pragma once
// The folders and programs of this build that the tests and benchmarks use, as absolute paths.
// Defined in a source file CMake generates per program (cmake/build_paths.cmake): the only
// source of a test or benchmark that holds the checkout's and the build's absolute paths, so
// that every other one compiles to the same object in any checkout and ccache serves it to a
// fresh clone.

namespace gfield::build_paths {

const char* data_dir();    ///< data/ of the checkout
const char* mesh_dir();    ///< data/meshes
const char* tests_dir();   ///< tests/ of the checkout
const char* fuzz_dir();    ///< tests/fuzz: fuzz targets' seeds and regression inputs
const char* test_tmp();    ///< the build's folder for the tests' files (tests/tmp in the build)
const char* cli();         ///< the `gfield` executable
const char* view();        ///< the `gfield-view` executable (runtime tests and benchmarks only)
const char* fault_shim();  ///< the fault injector preloaded into gfield (preprocess tests only)

}  // namespace gfield::build_paths
