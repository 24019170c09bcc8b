#!/usr/bin/env bash
# Installs the npm tools of the glTF conformance test (tests/scenes/gltf_conformance_test.sh):
# Khronos' glTF Validator (gltf-validator), obj2gltf and gltf-pipeline, at the versions of
# scripts/gltf-tools/package-lock.json, with `npm ci` from the npm registry into a cache folder
# outside the checkout (scripts/gltf-tools/location.sh: ~/.cache/gfield/gltf-tools/HASH), where
# every later run, CI's fresh copies included, finds them and installs nothing. gltfpack is a
# Debian package (scripts/install-deps.sh). A failed npm is retried three times (the registry or
# the network may fail for a moment), reusing npm's cache (~/.npm); the folder appears whole or
# not at all. Needs node >= 20.19 (gltf-pipeline's Cesium) and npm.
# Usage: scripts/install-gltf-tools.sh
set -euo pipefail
source "$(dirname "$0")/gltf-tools/location.sh"
if [ -f "$gltf_tools_dir/node_modules/.gfield-installed" ]; then
  echo "install-gltf-tools: up to date ($gltf_tools_dir)"
  exit 0
fi
start=$SECONDS
mkdir -p "$(dirname "$gltf_tools_dir")"
staging=$(mktemp -d "$gltf_tools_dir.XXXXXX")
trap 'rm -rf "$staging"' EXIT
cp "$gltf_tools_source/package.json" "$gltf_tools_source/package-lock.json" "$staging"
for attempt in 1 2 3; do
  if (cd "$staging" && npm ci --prefer-offline --no-audit --no-fund --loglevel=error \
    --fetch-retries=4 --fetch-retry-mintimeout=2000 --fetch-retry-maxtimeout=30000); then
    touch "$staging/node_modules/.gfield-installed"
    rm -rf "$gltf_tools_dir"
    mv "$staging" "$gltf_tools_dir"
    echo "install-gltf-tools: installed in $((SECONDS - start)) s ($gltf_tools_dir)"
    exit 0
  fi
  echo "install-gltf-tools: npm ci failed (attempt $attempt of 3)" >&2
  [ "$attempt" -lt 3 ] && sleep $((attempt * 15))
done
exit 1
