#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and runs the main job: the
# bundled meshes' topology, geometry images and geometry fields (beside the meshes in
# data/meshes/), then the mirror-torus scene rendered headless by gfield-view through the fields
# (out/mirror-torus.png), the same scene by the Embree reference tracer, and their PSNR.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh gfield gfield-view  # only what the demo runs; scripts/test.sh builds the rest
gfield=build/preprocess/gfield
mkdir -p out
echo "== gfield info data/meshes/spot.obj"
$gfield info data/meshes/spot.obj
for mesh in spot torus; do
  echo "== gfield build data/meshes/$mesh.obj -o data/meshes/$mesh"
  $gfield build "data/meshes/$mesh.obj" -o "data/meshes/$mesh"
done
scene=data/scenes/mirror-torus-instances.json
echo "== gfield-view $scene --headless --spp 8 --out out/mirror-torus.png"
build/runtime/gfield-view "$scene" --headless --spp 8 --out out/mirror-torus.png
echo "== gfield render $scene --spp 8 --strata-centres -o out/mirror-torus-reference.png"
$gfield render "$scene" --spp 8 --strata-centres -o out/mirror-torus-reference.png
echo "== gfield compare out/mirror-torus.png out/mirror-torus-reference.png"
$gfield compare out/mirror-torus.png out/mirror-torus-reference.png --heatmap out/mirror-torus-error.png
echo "Pictures in out/. Interactive viewer (needs a display): build/runtime/gfield-view $scene"
