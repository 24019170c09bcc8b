#!/usr/bin/env bash
# Builds gfield with AddressSanitizer and UndefinedBehaviorSanitizer (gcc, -O1 -g1, assertions and
# GF_DCHECKs on, benchmarks and the Python module off; cmake -DGFIELD_SANITIZE=ON) in build-asan/
# and runs the test suite
# there but for the Slurm cluster test, the glTF conformance test and five heavy end-to-end
# tests (below; docs/reliability.md; an
# instrumented Python module would need libasan preloaded into Debian's python3: docs/python.md).
# Any ASan or UBSan report fails its test; LeakSanitizer reports too, except for the leaks of
# Mesa's own drivers listed in tests/lsan-mesa.supp (the GL tests); a preloaded shim
# (tests/sanitizer/keep_libraries.c) keeps Mesa's driver loaded at eglTerminate so that its leaks
# carry its name.
# $GFIELD_JOBS sets the build jobs (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache-launcher.sh
# -O1 -g1 (line tables: symbolized reports with file and line): the optimisation level ASan
# recommends, and half the compile time of -O2 -g for the CGAL translation units (repair.cpp:
# 52 s against 126 s here). Without -DNDEBUG: the project's GF_DCHECKs (gfield/check.hpp) and the
# libraries' own assertions are on; -D_GLIBCXX_ASSERTIONS checks the standard containers' indices.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGFIELD_SANITIZE=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -D_GLIBCXX_ASSERTIONS" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DGFIELD_BUILD_BENCH=OFF -DGFIELD_BUILD_PYTHON=OFF "${launcher[@]}" > /dev/null
cmake --build build-asan -j "${GFIELD_JOBS:-2}"
cc -shared -fPIC -O2 -o build-asan/keep_libraries.so tests/sanitizer/keep_libraries.c
export LD_PRELOAD=$PWD/build-asan/keep_libraries.so
# intercept_tls_get_addr=0: LeakSanitizer scans no dynamic TLS (the blocks of libraries loaded by
# dlopen: Mesa's driver); it can take such a block for glibc 2.19's layout and scan a bogus range
# (google/sanitizers#1322; docs/reliability.md), which crashed its tracer.
export ASAN_OPTIONS=verify_asan_link_order=0:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan-mesa.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd build-asan
# Every test but the one-node Slurm cluster's (label "cluster"), the glTF conformance test's
# (label "gltf-tools": the npm tools; see tests/CMakeLists.txt), the web player's (label "web":
# chromium draws; gfield-view's part of it, the export, runs the code the render tests run) and five end-to-end tests that
# run, on larger inputs, code the faster tests run under the sanitizers too (every example
# scene's render, the glTF example's three asset builds, 512^2 and 1024^2 images, a batch of
# every rebuild, the viewer's refusals of outside paths; docs/reliability.md says what they
# cost). The release suite runs them all.
heavy='RenderTest\.ExampleScenesMatchReferenceTracer|ExampleScenes\.GltfExampleBuildsItsAssetsAndRenders'
heavy+='|GeometryImage\.AutomaticSizeDoublesUntilTheMeanErrorIsReached'
heavy+='|Batch\.UpToDateByContentNotByFileTimes|ExampleScenes\.ViewerConfinesTheFilesASceneNames'
if ! ctest --output-on-failure -j 2 --label-exclude 'cluster|gltf-tools|web' -E "$heavy"; then
  # LeakSanitizer's own stop-the-world tracer crashes ("Tracer caught signal 11",
  # google/sanitizers#1353) when a thread exits during its check at exit: TBB's workers did, and
  # the test programs and `gfield` now join them first (preprocess/worker_threads.hpp). Should it
  # still happen, with no sanitizer report, the failed tests are run once more
  # (docs/reliability.md).
  log=Testing/Temporary/LastTest.log
  if grep -q "Tracer caught signal" "$log" &&
      ! grep -qE "ERROR: (AddressSanitizer|LeakSanitizer): |runtime error:" "$log"; then
    # By name: ctest's numbers of gtest's discovered tests can differ between two runs.
    failed=$(sed -n 's/^[0-9]*:\(.*\)$/\1/p' Testing/Temporary/LastTestsFailed.log |
      sed 's/[][\.*^$+?(){}|]/\\&/g' | paste -sd '|')
    echo "sanitize.sh: LeakSanitizer's tracer crashed; running the failed tests once more: $failed"
    ctest --output-on-failure -R "^($failed)\$"
  else
    exit 1
  fi
fi
