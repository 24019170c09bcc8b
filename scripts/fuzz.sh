#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz (clang, ASan + UBSan; docs/reliability.md) in
# build-fuzz/, then for each target (all, or the ones named) replays its regressions and seeds and
# fuzzes it from the seeds, one target at a time at nice 19. Settings (environment):
#   GFIELD_FUZZ_SECONDS  fuzzing time per target (default 20)
#   GFIELD_FUZZ_RUNS     also stop a target after this many executions (default: no limit)
#   GFIELD_FUZZ_TIMEOUT  seconds one input may take before it counts as a hang (default 10)
#   GFIELD_FUZZ_CORPUS   folder that keeps each target's grown corpus (TARGET/ below it) between
#                        runs (default: a temporary folder, removed at the end)
# A crash, a sanitizer report, a hang, a single allocation above 2 GB or a broken contract
# (tests/fuzz/fuzz_support.hpp) stops with exit 1 and the input in build-fuzz/artifacts/TARGET/;
# fix it and copy the input to tests/fuzz/regressions/TARGET/. Usage: scripts/fuzz.sh [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache-launcher.sh
# -O1 -g1 as in scripts/sanitize.sh: libFuzzer's usual level, line tables for the reports.
cmake -S . -B build-fuzz -G Ninja -DGFIELD_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 "${launcher[@]}" > /dev/null
cmake --build build-fuzz -j "${GFIELD_JOBS:-2}"

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then  # every target: one per seed folder (tests/fuzz/CMakeLists.txt)
  mapfile -t targets < <(ls tests/fuzz/corpus)
fi
corpus_root=${GFIELD_FUZZ_CORPUS:-}
if [ -z "$corpus_root" ]; then
  corpus_root=$(mktemp -d "${TMPDIR:-/tmp}/gfield-fuzz-corpus.XXXXXX")
  trap 'rm -rf "$corpus_root"' EXIT
fi
limit=(-max_total_time="${GFIELD_FUZZ_SECONDS:-20}")
if [ -n "${GFIELD_FUZZ_RUNS:-}" ]; then
  limit+=(-runs="$GFIELD_FUZZ_RUNS")
fi
for t in "${targets[@]}"; do
  fuzzer=build-fuzz/tests/fuzz/fuzz_$t
  seeds=(tests/fuzz/corpus/"$t")
  if [ "$t" = scene ]; then
    seeds+=(data/scenes)
  fi
  artifacts=build-fuzz/artifacts/$t
  mkdir -p "$corpus_root/$t" "$artifacts"
  echo "== $t: replaying tests/fuzz/regressions/$t and the seeds"
  "$fuzzer" -runs=0 tests/fuzz/regressions/"$t" "${seeds[@]}" 2>&1 | grep -E "^Done|ERROR" || {
    echo "fuzz: $t fails on its regressions or seeds" >&2
    exit 1
  }
  echo "== $t: fuzzing (${limit[*]})"
  start=$(date +%s)
  nice -n 19 "$fuzzer" "${limit[@]}" -timeout="${GFIELD_FUZZ_TIMEOUT:-10}" -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "$corpus_root/$t" "${seeds[@]}" > "$artifacts/log.txt" 2>&1 || {
    tail -40 "$artifacts/log.txt" >&2
    echo "fuzz: $t found an input that breaks it (in $artifacts/)" >&2
    exit 1
  }
  stat() { sed -n "s/^stat::$1: *//p" "$artifacts/log.txt"; }
  echo "$t: $(stat number_of_executed_units) executions in $(($(date +%s) - start)) s," \
    "slowest input $(stat slowest_unit_time_sec) s, peak RSS $(stat peak_rss_mb) MB," \
    "corpus $(find "$corpus_root/$t" -type f | wc -l) files"
done
