#!/usr/bin/env bash
# CTest: `cmake --install BUILD --prefix P` into a temporary prefix, then, from another working
# directory and without the source tree's help: the installed gfield builds assets of an
# installed mesh, the installed gfield-view finds its shaders beside itself and renders installed
# example scenes headless with those assets, and an outside CMake project (tests/consumer) finds
# the package, links gfield::core, loads the field and looks it up; with PYTHON, the installed
# Python module imports from PREFIX/PYTHON_DIR (PYTHONPATH) and looks the field up too.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR [PYTHON PYTHON_DIR]
set -euo pipefail
build=$(cd "$1" && pwd)
source_dir=$(cd "$2" && pwd)
python=${3:-}
python_dir=${4:-}
work=$(mktemp -d "${TMPDIR:-/tmp}/gfield-install-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
unset GFIELD_SHADER_DIR

step() { echo "== $*"; }
fail() { echo "install_test: $*" >&2; exit 1; }

step "cmake --install $build --prefix $prefix"
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
for f in bin/gfield bin/gfield-view share/gfield/shaders/lib/field_lookup.glsl \
  share/gfield/shaders/field_trace.frag share/gfield/shaders/field_trace.comp \
  share/gfield/meshes/spot.obj \
  share/gfield/meshes/SOURCES.md share/gfield/scenes/mirror-torus-instances.json \
  share/gfield/.gfield-root \
  include/gfield/field_lookup.hpp lib/libgfield_core.a lib/cmake/gfield/gfieldConfig.cmake \
  lib/cmake/gfield/gfieldTargets.cmake; do
  [ -f "$prefix/$f" ] || fail "$prefix/$f: not installed"
done
if find "$prefix/share/gfield/meshes" -name '*.exr' -o -name '*.gimage.obj' | grep -q .; then
  fail "built assets were installed with the meshes"
fi

mkdir "$work/elsewhere"
cd "$work/elsewhere"
share="$prefix/share/gfield"
step "gfield-view --help names the installed shaders"
"$prefix/bin/gfield-view" --help | tr -s ' \n' ' ' | grep -qF "$share/shaders" ||
  fail "gfield-view does not default to $share/shaders"

step "gfield info / build on installed meshes"
"$prefix/bin/gfield" info "$share/meshes/spot.obj" > info.txt
grep -q "genus" info.txt || fail "gfield info printed no topology"
for mesh in spot torus; do
  "$prefix/bin/gfield" build "$share/meshes/$mesh.obj" -o "assets/$mesh" --size 128 --samples 8 \
    --verify-rays 1000 > "build-$mesh.log"
done

step "gfield-view --headless on installed example scenes"
"$prefix/bin/gfield-view" "$share/scenes/mirror-torus-instances.json" --assets assets --headless \
  --size 64x64 -o mirror.png
"$prefix/bin/gfield-view" "$share/scenes/two-mirror-spheres.json" --headless --size 64x64 \
  -o spheres.exr
"$prefix/bin/gfield-view" "$share/scenes/mukai-plate-tilt05-w02.json" --method glass --headless \
  --size 64x64 -o glass.png
for f in mirror.png spheres.exr glass.png; do
  [ -s "$f" ] || fail "$f: not written"
done
step "without --assets the viewer traces the meshes through their BVHs and says how to build"
"$prefix/bin/gfield-view" "$share/scenes/mirror-torus-instances.json" --headless --size 64x64 \
  -o bvh.png 2> missing.txt || fail "a scene without assets: $(cat missing.txt)"
[ -s bvh.png ] || fail "bvh.png: not written"
grep -q "no geometry field.*gfield build.*traced through its BVH" missing.txt ||
  fail "no note naming the missing field and how to build it: $(cat missing.txt)"
if "$prefix/bin/gfield-view" "$share/scenes/mirror-torus-instances.json" --headless \
  --method cubemap -o none.png 2> missing.txt; then
  fail "the cube-map method rendered a scene whose assets do not exist"
fi
grep -q "gfield build" missing.txt || fail "no hint how to build the assets: $(cat missing.txt)"

step "tests/consumer against $prefix"
cmake -S "$source_dir/tests/consumer" -B consumer -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > consumer-configure.log
cmake --build consumer > consumer-build.log || { cat consumer-build.log; fail "consumer build"; }
consumer/consumer assets/spot

if [ -n "$python" ]; then
  step "import gfield from $prefix/$python_dir"
  [ -f "$prefix/$python_dir/gfield/__init__.pyi" ] || fail "the module's stubs were not installed"
  PYTHONPATH="$prefix/$python_dir" PYTHONDONTWRITEBYTECODE=1 "$python" -c '
import sys
import numpy as np
import gfield
assert gfield.__file__.startswith(sys.argv[1]), gfield.__file__
field = gfield.GeometryField.load("assets/spot.gfield.exr")
centre = field.box.mean(axis=0)
hits = field.lookup([centre + [0, 0, 10]], [[0, 0, -1]])
assert hits["hit"][0] and np.all(np.abs(hits["normal"][0]) <= 1), hits
print("the installed module looked up", field)' "$prefix/$python_dir" ||
    fail "the installed Python module"
fi
echo "install_test: ok"
