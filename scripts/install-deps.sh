#!/usr/bin/env bash
# Installs the Debian 12 packages gfield needs, skipping those already installed, then the npm
# tools of the glTF conformance test (scripts/install-gltf-tools.sh: gltf-validator, obj2gltf,
# gltf-pipeline from the npm registry, once, into ~/.cache/gfield/gltf-tools/) and the web
# package's (scripts/install-web-deps.sh: web/node_modules from web/package-lock.json). Idempotent.
# Run as root (or with sudo available).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache dpkg-dev
  libcgal-dev libembree-dev libopenexr-dev libtbb-dev libeigen3-dev
  libglfw3-dev libglm-dev libepoxy-dev libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  libimgui-dev libcli11-dev nlohmann-json3-dev libstb-dev libtinygltf-dev
  # compressed glTF meshes: KHR_draco_mesh_compression, EXT_meshopt_compression
  libdraco-dev libmeshoptimizer-dev
  # the glTF conformance test (tests/scenes/gltf_conformance_test.sh): gltfpack, and node and npm
  # for the npm tools (gltf-pipeline's Cesium declares node >= 20.19; Debian 12's nodejs is 18,
  # a NodeSource nodejs 20 is kept where installed)
  gltfpack nodejs npm
  libgtest-dev libbenchmark-dev
  # the Python module (python/, docs/python.md), its tests and its worked example
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
  # the viewer's window test (tests/window/): an X server, synthetic input, screen grabs
  xvfb xdotool imagemagick
  # the Slurm test (tests/slurm/): a one-node cluster; Debian's packages start no daemon
  # where there is no systemd (the test starts its own on 127.0.0.1)
  slurmctld slurmd slurm-client munge jq
  clang libclang-rt-14-dev
  # the web player's test (web/test/player.test.mjs): a browser with WebGL2 (SwiftShader), and
  # zlib for the export's scene.bin.gz
  chromium zlib1g-dev
  # the layout check (scripts/check-format.sh)
  clang-format
  # the dialect test (scripts/check-glsl-dialect.py): shaders/lib compiled as GLSL by Khronos'
  # reference compiler
  glslang-tools
)

missing=()
for p in "${packages[@]}"; do
  # A node.js from elsewhere (NodeSource's nodejs bundles npm and conflicts with Debian's): its npm
  if [ "$p" = npm ] && command -v npm > /dev/null; then
    continue
  fi
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
else
  echo "install-deps: installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
"$(dirname "$0")/install-gltf-tools.sh"
"$(dirname "$0")/install-web-deps.sh"
