#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and runs the main job: the
# bundled meshes' topology, the geometry images and geometry fields of spot and the torus (into
# out/assets/, never beside the meshes in data/meshes/), then the mirror-torus scene rendered
# headless by gfield-view through those fields (out/mirror-torus.png), the same scene by the
# Embree reference tracer (out/mirror-torus-reference.png; it traces the meshes and needs no
# assets), and their PSNR. Everything it writes is under out/ (ignored by git).
# Usage: scripts/demo.sh [--no-build]   (--no-build: skip the package check and the build and run
# the tools already in build/; scripts/check-docs.sh runs it so in its fresh clone)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" != "--no-build" ]; then
  scripts/install-deps.sh
  scripts/build.sh gfield gfield-view  # only what the demo runs; scripts/test.sh builds the rest
fi
gfield=build/preprocess/gfield
mkdir -p out/assets
echo "== gfield info data/meshes/spot.obj"
$gfield info data/meshes/spot.obj
for mesh in spot torus; do
  echo "== gfield build data/meshes/$mesh.obj -o out/assets/$mesh"
  $gfield build "data/meshes/$mesh.obj" -o "out/assets/$mesh"
done
scene=data/scenes/mirror-torus-instances.json
echo "== gfield-view $scene --assets out/assets --headless --spp 8 --out out/mirror-torus.png"
build/runtime/gfield-view "$scene" --assets out/assets --headless --spp 8 --out out/mirror-torus.png
echo "== gfield render $scene --spp 8 --strata-centres -o out/mirror-torus-reference.png"
$gfield render "$scene" --spp 8 --strata-centres -o out/mirror-torus-reference.png
echo "== gfield compare out/mirror-torus.png out/mirror-torus-reference.png"
$gfield compare out/mirror-torus.png out/mirror-torus-reference.png --heatmap out/mirror-torus-error.png
echo "Pictures in out/. Interactive viewer (needs a display):"
echo "  build/runtime/gfield-view $scene --assets out/assets"
