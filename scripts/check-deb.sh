#!/usr/bin/env bash
# Builds the Debian package (cpack -G DEB in the build folder) and checks it with dpkg-deb: name,
# version and architecture, the Depends on the runtime Debian packages, the files it installs.
# Then unpacks it into a temporary root and runs the packaged gfield and gfield-view from there.
# With --install (as root) it also installs the package with apt, runs the installed commands
# from /tmp (build spot's assets, render an installed example scene headless) and removes it.
# Usage: scripts/check-deb.sh [--install] [BUILD_DIR]   (default build/, already built)
set -euo pipefail
cd "$(dirname "$0")/.."
install=0
if [ "${1:-}" = "--install" ]; then
  install=1
  shift
fi
build=$(cd "${1:-build}" && pwd)
fail() { echo "check-deb: $*" >&2; exit 1; }

version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
deb="$build/gfield_${version}_amd64.deb"
rm -f "$deb"
(cd "$build" && cpack -G DEB > cpack.log) || { cat "$build/cpack.log"; fail "cpack failed"; }
[ -f "$deb" ] || fail "$deb: not made (cpack made: $(ls "$build"/*.deb 2>/dev/null))"
echo "== $deb ($(du -h "$deb" | cut -f1))"

[ "$(dpkg-deb -f "$deb" Package)" = gfield ] || fail "package name"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "version"
[ "$(dpkg-deb -f "$deb" Architecture)" = amd64 ] || fail "architecture"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for p in libc6 libstdc++6 libembree3-3 libopenexr-3-1-30 libtbb12 libgmp10 \
  libglfw3 libepoxy0 libstb0 libegl1 libgl1 libgl1-mesa-dri; do
  [[ ", $depends," == *", $p "* || ", $depends," == *", $p,"* ]] || fail "Depends lacks $p"
done

contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for f in ./usr/bin/gfield ./usr/bin/gfield-view ./usr/share/gfield/shaders/lib/field_lookup.glsl \
  ./usr/share/gfield/meshes/spot.obj ./usr/share/gfield/meshes/SOURCES.md \
  ./usr/share/gfield/scenes/mirror-torus-instances.json ./usr/include/gfield/field_lookup.hpp \
  ./usr/lib/libgfield_core.a ./usr/lib/cmake/gfield/gfieldConfig.cmake; do
  grep -qxF "$f" <<< "$contents" || fail "$f: not in the package"
done
if grep -qE '\.exr$|\.gimage\.obj$|^./usr/local' <<< "$contents"; then
  fail "the package holds built assets or /usr/local paths"
fi
echo "contents: $(grep -c . <<< "$contents") entries, the expected ones present"

root=$(mktemp -d "${TMPDIR:-/tmp}/gfield-deb.XXXXXX")
trap 'rm -rf "$root"' EXIT
dpkg-deb -x "$deb" "$root"
(
  cd "$root"
  unset GFIELD_SHADER_DIR
  ./usr/bin/gfield info ./usr/share/gfield/meshes/suzanne.obj > /dev/null
  ./usr/bin/gfield-view --help | tr -s ' \n' ' ' | grep -qF "$root/usr/share/gfield/shaders" ||
    fail "the packaged gfield-view does not default to its own shaders"
  ./usr/bin/gfield-view ./usr/share/gfield/scenes/two-mirror-spheres.json --headless \
    --size 64x64 -o spheres.png
  [ -s spheres.png ] || fail "the packaged gfield-view wrote no picture"
)
echo "unpacked: gfield and gfield-view run from the package's own tree"

if [ "$install" = 1 ]; then
  echo "== apt-get install $deb"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq "$deb" > "$root/apt.log" || { cat "$root/apt.log"; fail "apt install"; }
  trap 'apt-get remove -y -qq gfield > /dev/null; rm -rf "$root"' EXIT
  (
    cd /tmp
    unset GFIELD_SHADER_DIR
    out=$(mktemp -d /tmp/gfield-installed.XXXXXX)
    gfield build /usr/share/gfield/meshes/spot.obj -o "$out/spot" --verify-rays 10000 > /dev/null
    gfield build /usr/share/gfield/meshes/torus.obj -o "$out/torus" --verify-rays 0 > /dev/null
    gfield-view /usr/share/gfield/scenes/mirror-torus-instances.json --assets "$out" --headless \
      --size 128x128 -o "$out/mirror.png"
    [ -s "$out/mirror.png" ] || fail "the installed gfield-view wrote no picture"
    rm -rf "$out"
  )
  echo "installed: gfield build and gfield-view ran from /tmp; package removed again"
fi
echo "check-deb: ok"
