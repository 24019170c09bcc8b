#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and runs the main job on the
# bundled mesh.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
echo "== gfield info data/meshes/spot.obj"
build/preprocess/gfield info data/meshes/spot.obj
