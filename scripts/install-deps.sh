#!/usr/bin/env bash
# Installs the Debian 12 packages gfield needs, skipping those already installed. Idempotent.
# Run as root (or with sudo available).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache dpkg-dev
  libcgal-dev libembree-dev libopenexr-dev libtbb-dev libeigen3-dev
  libglfw3-dev libglm-dev libepoxy-dev libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  libimgui-dev libcli11-dev nlohmann-json3-dev libstb-dev libtinygltf-dev
  libgtest-dev libbenchmark-dev
  # the Python module (python/, docs/python.md), its tests and its worked example
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
  # the viewer's window test (tests/window/): an X server, synthetic input, screen grabs
  xvfb xdotool imagemagick
  # the Slurm test (tests/slurm/): a one-node cluster; Debian's packages start no daemon
  # where there is no systemd (the test starts its own on 127.0.0.1)
  slurmctld slurmd slurm-client munge jq
  clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
