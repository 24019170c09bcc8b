#!/usr/bin/env bash
# Configures and builds gfield (Release) into build/ with 2 parallel jobs (CGAL translation
# units need 1-2 GB each). Arguments name the targets to build (default: all of them: tools,
# tests, benchmarks); $GFIELD_CMAKE_ARGS goes to cmake's configure step, $GFIELD_JOBS sets the
# jobs. ccache is used when installed.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache-launcher.sh
# shellcheck disable=SC2086
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" ${GFIELD_CMAKE_ARGS:-}
targets=()
for t in "$@"; do
  targets+=(--target "$t")
done
cmake --build build -j "${GFIELD_JOBS:-2}" "${targets[@]}"
