#!/usr/bin/env bash
# Configures and builds gfield-view with -DGFIELD_BUILD_PREPROCESS=OFF (build-viewer-only/) on a
# machine where CGAL's and Embree's headers and CMake packages are not there: inside a private
# mount namespace (unshare, root) their folders are covered by empty ones, so any #include of
# them or find_package for them fails. Then renders an example scene headless with that viewer
# and checks that it links neither Embree nor the preprocessing library. CI runs it.
# Usage: scripts/check-viewer-only.sh
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache's base folder the checkout's root, as for the other builds (scripts/ccache-launcher.sh):
# the cache then serves a clone in another folder (CI's copy) too.
source scripts/ccache-launcher.sh
if [ "$(id -u)" -ne 0 ]; then
  echo "check-viewer-only: needs root (unshare --mount)" >&2
  exit 2
fi
hidden=(/usr/include/CGAL /usr/include/embree3 /usr/lib/x86_64-linux-gnu/cmake/CGAL)
hidden+=(/usr/lib/x86_64-linux-gnu/cmake/embree-*)
build=build-viewer-only
rm -rf "$build"
# shellcheck disable=SC2016
unshare --mount bash -euo pipefail -c '
  empty=$(mktemp -d)
  for dir in "$@"; do
    [ -d "$dir" ] && mount --bind "$empty" "$dir"
  done
  [ ! -e /usr/include/CGAL/version.h ] && [ ! -e /usr/include/embree3/rtcore.h ]
  cmake -S . -B build-viewer-only -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DGFIELD_BUILD_PREPROCESS=OFF -DGFIELD_BUILD_TESTS=OFF -DGFIELD_BUILD_BENCH=OFF \
    $(command -v ccache > /dev/null && echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache) > /dev/null
  cmake --build build-viewer-only -j "${GFIELD_JOBS:-2}" --target gfield-view
' check-viewer-only "${hidden[@]}"
view="$build/runtime/gfield-view"
if ldd "$view" | grep -qi embree; then
  echo "check-viewer-only: $view links Embree" >&2
  exit 1
fi
if grep -q "gfield_preprocess\|libembree\|CGAL" "$build/build.ninja"; then
  echo "check-viewer-only: the viewer-only build names the preprocessing library, Embree or CGAL" >&2
  exit 1
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$view" data/scenes/two-mirror-spheres.json --headless --size 64x64 -o "$out/spheres.png"
"$view" data/scenes/mukai-plate-tilt05-w02.json --method glass --headless --size 64x64 \
  -o "$out/glass.png"
[ -s "$out/spheres.png" ] && [ -s "$out/glass.png" ]
echo "check-viewer-only: gfield-view built and ran without CGAL and Embree"
