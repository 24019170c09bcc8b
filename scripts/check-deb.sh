#!/usr/bin/env bash
# Builds the Debian package (cpack -G DEB in the build folder) and checks it with dpkg-deb: name,
# version and architecture, the Depends on the runtime Debian packages, the files it installs
# (exactly the expected ones: below). A build with the Python module makes a second package,
# python3-gfield, checked the same way.
# Then unpacks them into a temporary root and runs the packaged gfield and gfield-view from there,
# and imports the packaged module with PYTHONPATH. With --install (as root) it also installs the
# packages with apt, runs the installed commands from /tmp (build spot's assets, render an
# installed example scene headless; import gfield without PYTHONPATH, build and look up) and
# removes them.
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
# The Python module's files under the prefix (python/CMakeLists.txt); absent without the module.
shipped_python="$build/gfield-shipped-python.txt"
python_deb=""
if [ -s "$shipped_python" ]; then
  python_deb="$build/python3-gfield_${version}_amd64.deb"
fi
# The interpreter the module was built for: -DPython3_EXECUTABLE as given, or as FindPython3 found
# it (cmake/python.cmake: Debian's /usr/bin/python3 by default).
python=$(sed -n 's/^_\{0,1\}Python3_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt" | head -n 1)
[ -z "$python_deb" ] || [ -x "$python" ] ||
  fail "$build/CMakeCache.txt: no Python3_EXECUTABLE for the module (got '$python')"
rm -f "$build"/*.deb
(cd "$build" && cpack -G DEB > cpack.log) || { cat "$build/cpack.log"; fail "cpack failed"; }
for d in "$deb" $python_deb; do
  [ -f "$d" ] || fail "$d: not made (cpack made: $(ls "$build"/*.deb 2>/dev/null))"
  echo "== $d ($(du -h "$d" | cut -f1))"
done

[ "$(dpkg-deb -f "$deb" Package)" = gfield ] || fail "package name"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "version"
[ "$(dpkg-deb -f "$deb" Architecture)" = amd64 ] || fail "architecture"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for p in libc6 libstdc++6 libembree3-3 libopenexr-3-1-30 libtbb12 libgmp10 \
  libglfw3 libepoxy0 libstb0 libegl1 libgl1 libgl1-mesa-dri; do
  [[ ", $depends," == *", $p "* || ", $depends," == *", $p,"* ]] || fail "Depends lacks $p"
done

# The package holds exactly the expected files: the two tools, the core library and its CMake
# package, core's public headers, the shaders, and the scenes and meshes that cmake/install.cmake
# names (gfield-shipped-data.txt); anything else (a report or asset left beside an example
# scene, a stray file) fails, as does an expected file that is missing.
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$build/CMakeCache.txt" | tr '[:upper:]' '[:lower:]')
shipped="$build/gfield-shipped-data.txt"
[ -s "$shipped" ] || fail "$shipped: missing (configure the build folder again)"
[ -f "$build/gfield-web-vendor.txt" ] || fail "$build/gfield-web-vendor.txt: missing (configure the build folder again)"
expected=$(
  {
    printf '%s\n' bin/gfield bin/gfield-view lib/libgfield_core.a include/gfield/contract.glsl \
      lib/cmake/gfield/gfieldConfig.cmake lib/cmake/gfield/gfieldConfigVersion.cmake \
      lib/cmake/gfield/gfieldTargets.cmake "lib/cmake/gfield/gfieldTargets-$build_type.cmake"
    (cd core/include && find gfield -type f) | sed 's|^|include/|'
    (cd shaders && find . -type f \( -name '*.glsl' -o -name '*.vert' -o -name '*.frag' -o -name '*.comp' \)) |
      sed 's|^\./|share/gfield/shaders/|'
    printf '%s\n' share/gfield/web/player/index.html share/gfield/web/player/gfield-player.js \
      share/gfield/web/player/gfield-three-mesh-bvh.js
    # the vendor files of the three-mesh-bvh method that the build's configure found
    cat "$build/gfield-web-vendor.txt"
    cat "$shipped"
  } | sed 's|^|./usr/|' | sort
)
contents=$(dpkg-deb -c "$deb" | awk '$6 !~ /\/$/ {print $6}' | sort)
unexpected=$(comm -13 <(echo "$expected") <(echo "$contents"))
missing=$(comm -23 <(echo "$expected") <(echo "$contents"))
[ -z "$unexpected" ] || fail "the package holds files it should not:"$'\n'"$unexpected"
[ -z "$missing" ] || fail "the package lacks:"$'\n'"$missing"
# The shipped scenes and meshes are every file git tracks in data/scenes and data/meshes, and the
# marker that makes share/gfield their root (docs/scenes.md, "Confined paths").
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  tracked=$(git ls-files data/scenes data/meshes data/.gfield-root | sed 's|^data/|share/gfield/|' | sort)
  if [ "$tracked" != "$(sort "$shipped")" ]; then
    fail "cmake/install.cmake's lists differ from the files git tracks in data/ (< tracked, > listed):"$'\n'"$(diff <(echo "$tracked") <(sort "$shipped") | grep '^[<>]')"
  fi
fi
echo "contents: $(grep -c . <<< "$contents") files, exactly the expected ones"

if [ -n "$python_deb" ]; then
  [ "$(dpkg-deb -f "$python_deb" Package)" = python3-gfield ] || fail "python package name"
  [ "$(dpkg-deb -f "$python_deb" Version)" = "$version" ] || fail "python package version"
  depends=$(dpkg-deb -f "$python_deb" Depends)
  echo "python3-gfield Depends: $depends"
  for p in python3 python3-numpy libc6 libstdc++6 libembree3-3 libopenexr-3-1-30 libtbb12 libgmp10; do
    [[ ", $depends," == *", $p "* || ", $depends," == *", $p,"* ]] ||
      fail "python3-gfield's Depends lacks $p"
  done
  expected=$(sed 's|^|./usr/|' "$shipped_python" | sort)
  contents=$(dpkg-deb -c "$python_deb" | awk '$6 !~ /\/$/ {print $6}' | sort)
  [ "$contents" = "$expected" ] ||
    fail "python3-gfield holds (<) other files than the module's (>):"$'\n'"$(diff <(echo "$contents") <(echo "$expected") | grep '^[<>]')"
  echo "python3-gfield contents: $(grep -c . <<< "$contents") files, exactly the module's"
fi

root=$(mktemp -d "${TMPDIR:-/tmp}/gfield-deb.XXXXXX")
trap 'rm -rf "$root"' EXIT
for d in "$deb" $python_deb; do
  dpkg-deb -x "$d" "$root"
done
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
if [ -n "$python_deb" ]; then
  (
    cd "$root"
    PYTHONPATH="$root/usr/lib/python3/dist-packages" PYTHONDONTWRITEBYTECODE=1 "$python" -c '
import gfield, sys
assert gfield.__file__.startswith(sys.argv[1]), gfield.__file__
assert gfield.info(sys.argv[1] + "/usr/share/gfield/meshes/suzanne.obj")["faces"] == 968' "$root"
  ) || fail "the packaged module does not import or run"
  echo "unpacked: import gfield from the package's own tree"
fi

if [ "$install" = 1 ]; then
  echo "== apt-get install $deb $python_deb"
  export DEBIAN_FRONTEND=noninteractive
  # shellcheck disable=SC2086
  apt-get install -y -qq "$deb" $python_deb > "$root/apt.log" ||
    { cat "$root/apt.log"; fail "apt install"; }
  trap 'apt-get remove -y -qq gfield ${python_deb:+python3-gfield} > /dev/null; rm -rf "$root"' EXIT
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
  if [ -n "$python_deb" ]; then
    (
      cd /tmp
      out=$(mktemp -d /tmp/gfield-installed.XXXXXX)
      env -u PYTHONPATH PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -c '
import gfield, numpy, sys
assert gfield.__file__.startswith("/usr/lib/python3/dist-packages/gfield/"), gfield.__file__
gfield.build("/usr/share/gfield/meshes/spot.obj", sys.argv[1] + "/spot", size=64, samples=4,
             verify_rays=0)
field = gfield.GeometryField.load(sys.argv[1] + "/spot.gfield.exr")
hits = field.lookup(numpy.array([[0.0, 0.1, 5.0]]), numpy.array([[0.0, 0.0, -1.0]]))
assert hits["hit"][0], hits' "$out"
      rm -rf "$out"
    ) || fail "the installed module does not import or run"
  fi
  echo "installed: gfield build and gfield-view ran from /tmp${python_deb:+, and import gfield};" \
    "packages removed again"
fi
echo "check-deb: ok"
