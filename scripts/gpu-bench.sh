#!/usr/bin/env bash
# The runtime's benchmarks in one command, for a machine with a GPU (or, for comparison, any GL):
# builds what is missing (scripts/build.sh: Release, into build/), then writes into one markdown
# file (default out/gpu-bench.md) the GL renderer and
#   - bench_runtime_field: every mesh example scene and two-mirror-spheres at 1024^2 (or SIZE...),
#     depths 1, 2 and 4: the geometry field (nearest / linear / refined at depth 4) against exact
#     BVH tracing of the meshes, ms per frame, FPS, x the Embree reference tracer in the same run,
#     PSNR against it, GPU memory of each, and the work counters;
#   - bench_image_space_refraction: the Davis-Wyman paper's Table 1 (image-space refraction with
#     1-4 bounces, Wyman 2005, cube map, the geometry field);
#   - bench_glass --quick: the Mukai paper's Tables 1-3 (vertex-displacement refraction).
# Each part's wall time is printed as it ends, and each part's table is in OUT.md.partial as soon
# as it ends (a run cut short keeps what it finished); the whole run renames it to OUT.md. On a
# GPU machine run it as
#   scripts/gpu-bench.sh out/gpu-bench.md 1024
# Usage: scripts/gpu-bench.sh [OUT.md] [SIZE...]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/gpu-bench.md}
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1024)
benches=(bench_runtime_field bench_image_space_refraction bench_glass)
for b in "${benches[@]}"; do
  if [ ! -x "build/bench/$b" ]; then
    scripts/build.sh
    break
  fi
done
mkdir -p "$(dirname "$out")"
tmp="$out.partial"
{
  echo "# gfield runtime benchmarks"
  echo
  echo "$(date -u +%Y-%m-%dT%H:%MZ), $(uname -n), $(nproc) CPU cores;" \
    "GPU: $(nvidia-smi --query-gpu=name --format=csv,noheader 2> /dev/null || echo 'none found by nvidia-smi')"
  echo
} > "$tmp"
part() {
  local start=$SECONDS
  echo "gpu-bench: $*" >&2
  {
    echo
    echo "## \`$*\`"
    echo
    "$@"
  } >> "$tmp"
  echo "gpu-bench: $1 took $((SECONDS - start)) s" >&2
}
part build/bench/bench_runtime_field --frames 3 --depths 1,2,4 "${sizes[@]}"
part build/bench/bench_image_space_refraction "${sizes[@]}"
part build/bench/bench_glass --quick
mv "$tmp" "$out"
echo "gpu-bench: wrote $out"
