#!/usr/bin/env bash
# CTest: every example scene of data/scenes renders with `gfield render` (the reference tracer)
# and with `gfield-view --headless` (the scene's default method, the geometry fields), its mesh
# objects' assets built by `gfield build` into a temporary folder (small N to stay fast) and
# found there through --assets. Usage: example_scenes_test.sh GFIELD GFIELD_VIEW DATA_DIR
set -euo pipefail
gfield=$1
view=$2
data=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/gfield-scenes-test.XXXXXX")
trap 'rm -rf "$work"' EXIT

meshes=$(grep -ho '"file": *"[^"]*"' "$data"/scenes/*.json | sed 's/.*"\([^"]*\)"$/\1/' | sort -u)
for mesh in $meshes; do
  path="$data/scenes/$mesh"
  [ -f "$path" ] || { echo "$path: named by an example scene, not in the repository" >&2; exit 1; }
  name=$(basename "$path" .obj)
  echo "== gfield build $name"
  "$gfield" build "$path" -o "$work/assets/$name" --size 128 --samples 8 --verify-rays 0 > /dev/null
done
count=0
for scene in "$data"/scenes/*.json; do
  name=$(basename "$scene" .json)
  echo "== $name"
  "$gfield" render "$scene" --size 48x48 --spp 1 -q -o "$work/$name-reference.png"
  "$view" "$scene" --assets "$work/assets" --headless --size 48x48 -o "$work/$name-view.png"
  [ -s "$work/$name-reference.png" ] && [ -s "$work/$name-view.png" ]
  count=$((count + 1))
done
[ "$count" -ge 9 ] || { echo "only $count example scenes" >&2; exit 1; }
echo "example_scenes_test: $count scenes rendered by both"
