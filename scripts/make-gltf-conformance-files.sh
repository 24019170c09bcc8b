#!/usr/bin/env bash
# Makes glTF files as the ecosystem's tools write them, from the bundled meshes, for the glTF
# conformance test (tests/scenes/gltf_conformance_test.sh; docs/scenes.md, "glTF conformance"):
# obj2gltf (.glb, .gltf with embedded data, .gltf with separate resources), gltf-pipeline (Draco,
# separate resources), gltfpack (default: KHR_mesh_quantization with KHR_texture_transform;
# normalised positions; coarse quantisation; EXT_meshopt_compression, with filters; none). The
# npm tools come from scripts/install-gltf-tools.sh, gltfpack from Debian. Writes OUT_DIR/NAME
# (and folders of separate resources) and OUT_DIR/files.txt, one line per file:
# "FILE SOURCE_OBJ TOOL COMMAND...". The files are made afresh each time, never committed.
# Usage: scripts/make-gltf-conformance-files.sh OUT_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/scripts/gltf-tools/location.sh"
tools=$gltf_tools_bin
out=$1
for tool in "$tools/obj2gltf" "$tools/gltf-pipeline"; do
  [ -x "$tool" ] || { echo "make-gltf-conformance-files: $tool missing (run scripts/install-gltf-tools.sh)" >&2; exit 2; }
done
command -v gltfpack > /dev/null || { echo "make-gltf-conformance-files: gltfpack missing (Debian package gltfpack)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
list="$out/files.txt"
: > "$list"
# produce FILE SOURCE TOOL ARGS...: runs TOOL ARGS in OUT_DIR (they write FILE), records it.
produce() {
  local file=$1 source=$2 tool=$3
  shift 3
  local program=$tool log
  [ "$tool" = gltfpack ] || program="$tools/$tool"
  log="$out/${file//\//_}.log"
  (cd "$out" && "$program" "$@" > "$log" 2>&1) ||
    { cat "$log" >&2; echo "make-gltf-conformance-files: $tool $* failed" >&2; exit 1; }
  rm -f "$log"
  echo "$file $source $tool $*" >> "$list"
}
meshes="$root/data/meshes"
for mesh in spot-painted torus; do
  m="$meshes/$mesh.obj"
  produce "$mesh.obj2gltf.glb" "$mesh.obj" obj2gltf -i "$m" -o "$mesh.obj2gltf.glb"
  produce "$mesh.obj2gltf.gltf" "$mesh.obj" obj2gltf -i "$m" -o "$mesh.obj2gltf.gltf"
  produce "$mesh.pipeline-draco.glb" "$mesh.obj" gltf-pipeline -i "$mesh.obj2gltf.glb" \
    -o "$mesh.pipeline-draco.glb" -d
  produce "$mesh.gltfpack-cc.glb" "$mesh.obj" gltfpack -i "$mesh.obj2gltf.glb" -o "$mesh.gltfpack-cc.glb" -cc
done
m="$meshes/spot-painted.obj"
produce "obj2gltf-separate/spot-painted.gltf" spot-painted.obj obj2gltf -i "$m" \
  -o obj2gltf-separate/spot-painted.gltf --separate
produce "pipeline-separate/spot-painted.gltf" spot-painted.obj gltf-pipeline \
  -i spot-painted.obj2gltf.glb -o pipeline-separate/spot-painted.gltf -s
for variant in default:"" vpn:"-vpn" coarse:"-vp 10 -vt 10" c:"-c" noq:"-noq"; do
  name=${variant%%:*}
  # shellcheck disable=SC2086
  produce "spot-painted.gltfpack-$name.glb" spot-painted.obj gltfpack -i spot-painted.obj2gltf.glb \
    -o "spot-painted.gltfpack-$name.glb" ${variant#*:}
done
produce "spot-painted.gltfpack-obj.glb" spot-painted.obj gltfpack -i "$m" -o spot-painted.gltfpack-obj.glb
echo "make-gltf-conformance-files: $(wc -l < "$list") files in $out"
