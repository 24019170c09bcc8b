#!/usr/bin/env bash
# Configures and builds gfield (Release) into build/ with 2 parallel jobs (CGAL translation
# units need 1-2 GB each). Extra arguments go to cmake's configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j "${GFIELD_JOBS:-2}"
