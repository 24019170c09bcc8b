# Sourced (bash): where the npm tools of the glTF conformance test live, outside the checkout so
# that CI's fresh copy of the tree (.ci/run) finds them installed: one folder per version of
# package-lock.json, ${GFIELD_GLTF_TOOLS_CACHE:-${XDG_CACHE_HOME:-~/.cache}/gfield/gltf-tools}/
# HASH (the lock's sha256, 16 digits). Sets gltf_tools_source (this folder), gltf_tools_dir
# (the installed package; node_modules/ below it) and gltf_tools_bin (its node_modules/.bin).
gltf_tools_source=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
gltf_tools_dir="${GFIELD_GLTF_TOOLS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/gfield/gltf-tools}/$(
  sha256sum "$gltf_tools_source/package-lock.json" | cut -c1-16)"
gltf_tools_bin="$gltf_tools_dir/node_modules/.bin"
