#!/usr/bin/env bash
# CTest: gfield-view confines the files a scene names as gfield does, and
# --allow-outside-paths lifts the rule, for its own reading and for the `gfield assets` it runs: a
# JSON scene naming an environment image above its folder, and a glTF file whose buffer lies
# above its folder, are refused (exit 2, one line naming the scene, the place and the path) and
# render with the option.
# Usage: confined_paths_view_test.sh GFIELD GFIELD_VIEW FUZZ_DIR
set -euo pipefail
gfield=$1
view=$2
fuzz=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/gfield-confined-view.XXXXXX")
trap 'rm -rf "$work"' EXIT

fail() { echo "confined_paths_view_test: $*" >&2; exit 1; }
# expect_refused TEXT... -- ARGS...: gfield-view ARGS exits 2 with one stderr line holding each TEXT.
expect_refused() {
  local texts=()
  while [ "$1" != -- ]; do texts+=("$1"); shift; done
  shift
  local status=0
  "$view" "$@" > "$work/out.txt" 2> "$work/err.txt" || status=$?
  [ "$status" = 2 ] || fail "exit $status (expected 2): $(cat "$work/err.txt")"
  [ "$(wc -l < "$work/err.txt")" = 1 ] || fail "not one line: $(cat "$work/err.txt")"
  for text in "${texts[@]}"; do
    grep -qF -- "$text" "$work/err.txt" || fail "does not say $text: $(cat "$work/err.txt")"
  done
  [ ! -e "$work/view.png" ] || fail "wrote a picture"
}

# A JSON scene whose environment image lies above its folder.
mkdir -p "$work/scenes"
cat > "$work/sky.json" << 'SCENE'
{"camera": {"position": [0, 0, 4], "target": [0, 0, 0]}, "environment": {"type": "studio"}}
SCENE
"$gfield" render "$work/sky.json" --size 32x16 -q -o "$work/sky.png"
cat > "$work/scenes/scene.json" << 'SCENE'
{"camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
 "environment": {"type": "equirect", "file": "../sky.png"},
 "objects": [{"shape": "sphere", "material": {"type": "mirror"}}]}
SCENE
expect_refused "$work/scenes/scene.json:" environment.file '"../sky.png" leaves' -- \
  "$work/scenes/scene.json" --headless --size 16x16 -o "$work/view.png"
"$view" "$work/scenes/scene.json" --allow-outside-paths --headless --size 16x16 \
  -o "$work/view.png" 2> "$work/err.txt" || fail "refused with the option: $(cat "$work/err.txt")"
[ -s "$work/view.png" ] || fail "no picture with the option"
rm "$work/view.png"

# A glTF tetrahedron whose buffer lies above its folder: gfield-view and the `gfield assets` it
# runs to build the mesh's assets.
mkdir -p "$work/gltf/inner"
data=$(grep -o 'base64,[^"]*' "$fuzz/corpus/mesh_gltf/tetrahedron.gltf")
echo "${data#base64,}" | base64 -d > "$work/gltf/tet.bin"
sed 's|"uri":"data:[^"]*"|"uri":"../tet.bin"|' "$fuzz/corpus/mesh_gltf/tetrahedron.gltf" \
  > "$work/gltf/inner/tet.gltf"
expect_refused "$work/gltf/inner/tet.gltf:" /buffers/0/uri '"../tet.bin" leaves' -- \
  "$work/gltf/inner/tet.gltf" --headless --size 16x16 -o "$work/view.png"
# gfield-view runs $GFIELD_CLI: a wrapper that records its arguments.
cat > "$work/gfield-wrapper" << WRAPPER
#!/usr/bin/env bash
echo "\$*" >> "$work/gfield-arguments.txt"
exec "$gfield" "\$@"
WRAPPER
chmod +x "$work/gfield-wrapper"
GFIELD_CLI="$work/gfield-wrapper" "$view" "$work/gltf/inner/tet.gltf" --allow-outside-paths \
  --assets "$work/assets" --headless --size 16x16 -o "$work/view.png" 2> "$work/err.txt" ||
  fail "refused with the option: $(cat "$work/err.txt")"
grep -qF -- "assets $work/gltf/inner/tet.gltf --assets $work/assets --allow-outside-paths" \
  "$work/gfield-arguments.txt" || fail "gfield assets ran without the option: $(cat "$work/gfield-arguments.txt")"
[ -s "$work/view.png" ] || fail "no picture of the glTF scene with the option"
ls "$work/assets"/tet.0-tetrahedron.gfield.exr > /dev/null || fail "gfield assets built nothing"
echo "confined_paths_view_test: refused without --allow-outside-paths, rendered with it"
