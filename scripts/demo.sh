#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and runs the main job on the
# bundled mesh: its topology, then its geometry image and geometry field (out/spot.*).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
echo "== gfield info data/meshes/spot.obj"
build/preprocess/gfield info data/meshes/spot.obj
echo "== gfield build data/meshes/spot.obj -o out/spot"
build/preprocess/gfield build data/meshes/spot.obj -o out/spot
