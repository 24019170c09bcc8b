#!/usr/bin/env bash
# CTest: glTF as the ecosystem writes it, with the real tools. Makes third-party files
# from the bundled meshes (scripts/make-gltf-conformance-files.sh: obj2gltf, gltf-pipeline,
# gltfpack) and checks each: `gfield info` and a 64^2 `gfield render` of the file succeed, and the
# file, placed in a scene with a fixed camera and light, renders (reference tracer, 64^2, 4
# samples at the strata centres) like its source OBJ in the same scene: PSNR >= 40 dB, also for
# gltfpack's coarse quantisation (-vp 10 -vt 10: positions on a grid of 1/1023 of the box). A file requiring an extension gfield does not implement exits 2 naming it,
# with no picture. Every example scene exported by `gfield export-gltf` validates with
# Khronos' glTF Validator: 0 errors, 0 warnings. Prints the table of docs/scenes.md.
# Usage: gltf_conformance_test.sh GFIELD SOURCE_DIR
set -euo pipefail
gfield=$1
source_dir=$(cd "$2" && pwd)
source "$source_dir/scripts/gltf-tools/location.sh"
[ -f "$gltf_tools_dir/node_modules/.gfield-installed" ] ||
  { echo "the glTF tools are not installed: run scripts/install-gltf-tools.sh" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/gfield-gltf-conformance.XXXXXX")
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
start=$SECONDS

echo "== third-party files"
"$source_dir/scripts/make-gltf-conformance-files.sh" "$work"
cp "$source_dir"/data/meshes/{spot-painted.obj,spot-painted.mtl,spot-painted.png,torus.obj} "$work"

# scene NAME OBJECT: a scene of one object (JSON) with the camera and light of SOURCE's mesh.
scene() {
  local camera='"position": [1.5, 0.6, -2.4], "target": [0, 0.1, -0.05], "fov": 40'
  [[ $1 == torus* ]] && camera='"position": [0, 2.6, 3.4], "target": [0, 0, 0], "fov": 45'
  cat > "$work/$1.json" <<JSON
{"camera": {$camera}, "image": {"width": 64, "height": 64}, "ambient": 0.3,
 "lights": [{"type": "directional", "direction": [-0.4, -1, -0.6], "intensity": 0.9}],
 "objects": [$2]}
JSON
}
render() {
  "$gfield" render "$work/$1.json" --spp 4 --strata-centres -q -o "$work/$1.png"
}
# The sources. The torus has no material: obj2gltf gives such a mesh its default, grey 0.5.
scene spot-painted-obj '{"shape": "mesh", "file": "spot-painted.obj", "material": {"type": "diffuse"}}'
scene torus-obj '{"shape": "mesh", "file": "torus.obj", "material": {"type": "diffuse", "color": 0.5}}'
render spot-painted-obj
render torus-obj
failures=0
printf '%-36s %-44s %10s\n' "file" "made by" "PSNR" > "$work/table.txt"
while read -r file source tool args; do
  name=${file//\//_}
  "$gfield" info "$work/$file" > "$work/$name.info" 2> "$work/$name.err" ||
    { echo "FAIL $file: gfield info: $(cat "$work/$name.err")"; failures=$((failures + 1)); continue; }
  "$gfield" render "$work/$file" --size 64x64 --spp 1 -q -o "$work/$name.direct.png" \
    2> "$work/$name.err" ||
    { echo "FAIL $file: gfield render: $(cat "$work/$name.err")"; failures=$((failures + 1)); continue; }
  scene "$name" "{\"shape\": \"gltf\", \"file\": \"$file\"}"
  render "$name" 2> "$work/$name.err" ||
    { echo "FAIL $file: $(cat "$work/$name.err")"; failures=$((failures + 1)); continue; }
  psnr=$("$gfield" compare "$work/${source%.obj}-obj.png" "$work/$name.png" | awk '$1 == "PSNR" {print $2}')
  bound=40
  made="$tool ${args//$source_dir\/data\/meshes\//}"
  made=${made//-o $file/}
  printf '%-36s %-44s %7s dB\n' "$file" "${made//  / }" "$psnr" >> "$work/table.txt"
  awk -v p="$psnr" -v b="$bound" 'BEGIN { exit !(p == "inf" || p >= b) }' ||
    { echo "FAIL $file: PSNR $psnr dB against $source, below $bound dB"; failures=$((failures + 1)); }
  [ -s "$work/$name.err" ] && echo "$file: $(cat "$work/$name.err")"
done < "$work/files.txt"
cat "$work/table.txt"

echo "== a file requiring an extension gfield does not implement"
jq '.extensionsUsed += ["EXT_gfield_conformance_unknown"] |
    .extensionsRequired += ["EXT_gfield_conformance_unknown"]' \
  "$work/spot-painted.obj2gltf.gltf" > "$work/requires-unknown.gltf"
for command in info render; do
  args=("$work/requires-unknown.gltf")
  [ "$command" = render ] && args+=(-o "$work/requires-unknown.png")
  status=0
  "$gfield" "$command" "${args[@]}" > /dev/null 2> "$work/unknown.err" || status=$?
  cat "$work/unknown.err"
  if [ "$status" -ne 2 ] || [ "$(wc -l < "$work/unknown.err")" -ne 1 ] ||
    ! grep -q "requires-unknown.gltf.*EXT_gfield_conformance_unknown" "$work/unknown.err" ||
    [ -e "$work/requires-unknown.png" ]; then
    echo "FAIL gfield $command of a file requiring an unknown extension: exit $status"
    failures=$((failures + 1))
  fi
done

echo "== gfield export-gltf of every example scene, validated"
mkdir "$work/exports"
for example in "$source_dir"/data/scenes/*.json "$source_dir"/data/scenes/*.glb; do
  name=$(basename "$example")
  "$gfield" export-gltf "$example" -o "$work/exports/${name%.*}.${name##*.}.glb" > /dev/null
done
NODE_PATH="$gltf_tools_dir/node_modules" node "$gltf_tools_source/validate.js" "$work"/exports/*.glb ||
  { echo "FAIL: the validator reports errors or warnings"; failures=$((failures + 1)); }

echo "gltf_conformance_test: $failures failures, $((SECONDS - start)) s"
[ "$failures" -eq 0 ]
