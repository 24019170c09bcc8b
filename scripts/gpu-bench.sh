#!/usr/bin/env bash
# The runtime's benchmarks in one command, for a machine with a GPU (or, for comparison, any GL):
# builds what is missing (scripts/build.sh: Release, into build/), then writes into one markdown
# file (default out/gpu-bench.md) the device, the commit and
#   - bench_runtime_field: Li et al.'s scenes (every mesh example scene and two-mirror-spheres)
#     at SIZE^2 (default 1024), depths 1-4: the geometry field (refined) against exact BVH
#     tracing of the meshes, in the compute and in the fragment pass (at depth 4 also the
#     nearest and linear lookups, in the compute pass);
#     wall and GPU ms (median and range), x the Embree reference tracer in the same run, PSNR
#     against it, GPU memory and the work counters;
#   - bench_image_space_refraction: the Davis-Wyman paper's Table 1 (image-space refraction with
#     1-4 bounces, Wyman 2005, cube map, the geometry field);
#   - bench_glass --quick: the Mukai paper's Tables 1-3 (vertex-displacement refraction).
# Every row times FRAMES frames (default 10) after warm-up frames until two agree
# (runtime/frame_timing.hpp) and flags a range over 10% of its median. The parts share one time
# budget (GPU_BENCH_SECONDS, default 480): a part
# still running when it is spent is stopped, and the rows it printed are kept. Each part's rows
# are in OUT.md.partial as they are measured; the whole run renames it to OUT.md. On a GPU
# machine run it as
#   scripts/gpu-bench.sh out/gpu-bench.md 1024
# Usage: scripts/gpu-bench.sh [OUT.md] [SIZE...]    (environment: FRAMES, GPU_BENCH_SECONDS)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/gpu-bench.md}
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1024)
frames=${FRAMES:-10}
budget=${GPU_BENCH_SECONDS:-480}
benches=(bench_runtime_field bench_image_space_refraction bench_glass)
for b in "${benches[@]}"; do
  if [ ! -x "build/bench/$b" ]; then
    scripts/build.sh "${benches[@]}"
    break
  fi
done
mkdir -p "$(dirname "$out")"
tmp="$out.partial"
start=$SECONDS
{
  echo "# gfield runtime benchmarks"
  echo
  echo "$(date -u +%Y-%m-%dT%H:%MZ), commit $(git rev-parse --short HEAD 2> /dev/null || echo unknown)," \
    "$(uname -n), $(nproc) CPU cores;" \
    "GPU: $(nvidia-smi --query-gpu=name --format=csv,noheader 2> /dev/null || echo 'none found by nvidia-smi');" \
    "$frames timed frames a row, a budget of $budget s"
  echo
} > "$tmp"
# part COMMAND...: runs COMMAND (its stdout appended to the file as it comes) within what is
# left of the budget; a part cut short says so in the file.
part() {
  local left=$((budget - (SECONDS - start)))
  echo "gpu-bench: $* ($left s of the budget left)" >&2
  {
    echo
    echo "## \`$*\`"
    echo
  } >> "$tmp"
  if [ "$left" -le 0 ]; then
    echo "Not run: the budget of $budget s was spent." >> "$tmp"
    return
  fi
  local part_start=$SECONDS rc=0
  timeout -k 10 "$left" "$@" >> "$tmp" || rc=$?
  if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    printf '\nStopped after %d s: the budget of %d s was spent; the rows above were measured.\n' \
      $((SECONDS - part_start)) "$budget" >> "$tmp"
  elif [ "$rc" -ne 0 ]; then
    printf '\nExited with status %d.\n' "$rc" >> "$tmp"
  fi
  echo "gpu-bench: $1 took $((SECONDS - part_start)) s" >&2
}
part build/bench/bench_runtime_field --frames "$frames" --depths 1,2,3,4 "${sizes[@]}"
part build/bench/bench_image_space_refraction --frames "$frames" "${sizes[@]}"
part build/bench/bench_glass --quick --frames "$frames"
mv "$tmp" "$out"
echo "gpu-bench: wrote $out in $((SECONDS - start)) s"
