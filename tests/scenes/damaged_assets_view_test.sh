#!/usr/bin/env bash
# CTest: gfield-view refuses damaged assets and absurd scenes as gfield does: a
# geometry image whose header claims 60000^2 texels (it used to abort on std::bad_alloc), the
# other damaged geometry images and fields of tests/fuzz/regressions, and the damaged scenes
# there: exit 2, one line on stderr naming the file, no picture.
# Usage: damaged_assets_view_test.sh GFIELD GFIELD_VIEW FUZZ_DIR
set -euo pipefail
gfield=$1
view=$2
fuzz=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/gfield-damaged-view.XXXXXX")
trap 'rm -rf "$work"' EXIT

fail() { echo "damaged_assets_view_test: $*" >&2; exit 1; }
# expect_refused FILE ARGS...: gfield-view ARGS exits 2 with one stderr line naming FILE.
expect_refused() {
  local file=$1
  shift
  local status=0
  "$view" "$@" > "$work/out.txt" 2> "$work/err.txt" || status=$?
  [ "$status" = 2 ] || fail "exit $status (expected 2) for $file: $(cat "$work/err.txt")"
  [ "$(wc -l < "$work/err.txt")" = 1 ] || fail "not one line for $file: $(cat "$work/err.txt")"
  grep -qF "$file" "$work/err.txt" || fail "does not name $file: $(cat "$work/err.txt")"
  [ ! -e "$work/view.png" ] || fail "wrote a picture for $file"
}

cp "$fuzz/corpus/mesh_obj/tetrahedron.obj" "$work/tet.obj"
"$gfield" build "$work/tet.obj" -o "$work/good/tet" --size 8 --samples 4 --verify-rays 0 > /dev/null
cat > "$work/scene.json" << 'SCENE'
{"camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
 "objects": [{"shape": "mesh", "file": "tet.obj", "material": {"type": "mirror"}}]}
SCENE
"$view" "$work/scene.json" --assets "$work/good" --headless --size 16x16 -o "$work/good.png"
[ -s "$work/good.png" ] || fail "the undamaged asset does not render"

count=0
for kind in gimage gfield; do
  for damaged in "$fuzz/regressions/$kind"/*; do
    rm -rf "$work/assets" && cp -r "$work/good" "$work/assets"
    cp "$damaged" "$work/assets/tet.$kind.exr"
    expect_refused "$work/assets/tet.$kind.exr" "$work/scene.json" --assets "$work/assets" \
      --headless --size 16x16 -o "$work/view.png"
    count=$((count + 1))
  done
done
for scene in "$fuzz/regressions/scene"/*.json; do
  expect_refused "$scene" "$scene" --headless --size 16x16 -o "$work/view.png"
  count=$((count + 1))
done
echo "damaged_assets_view_test: $count damaged inputs refused"
