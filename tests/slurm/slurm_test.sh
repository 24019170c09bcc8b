#!/usr/bin/env bash
# On a real one-node Slurm cluster (tests/slurm/cluster.sh): the bundled meshes built by
# scripts/slurm/gfield-batch.sbatch as a 4-task job array equal a single-process `gfield batch`
# of the same inputs (same files; images, meshes and fields byte-identical; reports equal but for
# their times); then one task of a second array is cancelled with scancel in the middle of a
# mesh, its shard resubmitted alone, and every asset must be complete, pass `gfield verify` and
# equal the single-process build, with the resubmitted task skipping what the cancelled one
# finished. Prints the wall times of the single process and the array.
#
# Usage: slurm_test.sh GFIELD SOURCE_DIR [build options] (default: --size 128 --samples 8
# --verify-rays 2000). CTest runs it inside `unshare --pid --fork --mount-proc --kill-child`, so
# that everything it starts dies with it; the daemons are stopped by their PIDs at exit.
set -euo pipefail
gfield=$(realpath "$1")
source_dir=$(realpath "$2")
shift 2
options=("$@")
[ ${#options[@]} -gt 0 ] || options=(--size 128 --samples 8 --verify-rays 2000)
meshes=$source_dir/data/meshes
sbatch_script=$source_dir/scripts/slurm/gfield-batch.sbatch
for tool in slurmctld slurmd sbatch munged mungekey jq; do
  command -v "$tool" > /dev/null || {
    echo "slurm_test: $tool not installed (scripts/install-deps.sh installs it)" >&2
    exit 1
  }
done
# shellcheck source=tests/slurm/cluster.sh
source "$source_dir/tests/slurm/cluster.sh"

work=$(mktemp -d "${TMPDIR:-/tmp}/gfield-slurm.XXXXXX")
finish() {
  local status=$?
  if [ $status -ne 0 ] && [ -d "$work/cluster/log" ]; then
    echo "--- logs" >&2
    tail -n 30 "$work"/cluster/log/* "$work"/*/gfield-batch-*.log 2> /dev/null >&2 || true
  fi
  cluster_stop || status=1
  rm -rf "$work"
  [ $status -eq 0 ] && echo "slurm_test: passed in $SECONDS s" || echo "slurm_test: FAILED" >&2
  exit $status
}
trap finish EXIT
fail() {
  echo "slurm_test: $*" >&2
  exit 1
}

cluster_start "$work/cluster"

# Submits the array script from folder $1 (outputs in $1/assets); extra sbatch options follow.
submit() {
  local dir=$1
  shift
  mkdir -p "$dir"
  sbatch --parsable --chdir="$dir" --output="$dir/gfield-batch-%A_%a.log" \
    --export="ALL,GFIELD=$gfield" "$@" "$sbatch_script" "$meshes" -o assets "${options[@]}"
}

# Every task of job $1 completed with exit code 0.
check_completed() {
  local states
  states=$(scontrol -o show job "$1" | grep -o 'JobState=[A-Z]* .* ExitCode=[0-9:]*' |
    sed 's/JobState=\([A-Z]*\) .* ExitCode=\([0-9:]*\)/\1 \2/' | sort | uniq -c)
  echo "job $1: $states"
  [ "$(echo "$states" | grep -cv 'COMPLETED 0:0')" -eq 0 ] || fail "job $1 has failed tasks"
}

# The assets of folder $1 equal those of $2: same file names; EXR and OBJ files byte-identical;
# reports equal without their times.
compare_assets() {
  local a=$1 b=$2 f strip
  strip='walk(if type == "object" then with_entries(select(.key | test("seconds") | not)) else . end)'
  diff <(cd "$a" && ls | grep -v '^manifest-') <(cd "$b" && ls | grep -v '^manifest-') ||
    fail "$a and $b hold different files"
  for f in "$a"/*.exr "$a"/*.obj; do
    cmp "$f" "$b/$(basename "$f")" || fail "$f differs"
  done
  for f in "$a"/*.report.json; do
    diff <(jq -S "$strip" "$f") <(jq -S "$strip" "$b/$(basename "$f")") ||
      fail "$f differs beyond its times"
  done
  echo "identical: $(ls "$a"/*.exr "$a"/*.obj | wc -l) EXR/OBJ files and" \
    "$(ls "$a"/*.report.json | wc -l) reports of $a and $b"
}

count=$(ls "$meshes"/*.obj | wc -l)
start=$SECONDS
(cd "$work" && mkdir single && cd single &&
  "$gfield" batch "$meshes" -o assets "${options[@]}" > batch.log 2>&1) ||
  fail "single-process batch failed: $(tail -n 3 "$work/single/batch.log")"
single_seconds=$((SECONDS - start))

start=$SECONDS
job=$(submit "$work/array" --array=0-3 --cpus-per-task=1)
cluster_wait_job "$job"
array_seconds=$((SECONDS - start))
check_completed "$job"
"$gfield" batch --summary "$work/array/assets" || fail "the array's summary shows failures"
compare_assets "$work/single/assets" "$work/array/assets"
echo "throughput: $count meshes, one process (all $(nproc) cores) ${single_seconds} s," \
  "4-task array (1 CPU each) ${array_seconds} s"

# Cancel the task whose shard holds the largest mesh once it is inside that mesh's build.
shard=""
for i in 0 1 2 3; do
  if "$gfield" batch "$meshes" -o "$work/resume/assets" --shard "$i/4" --list "${options[@]}" |
    grep -q '/stanford-bunny.obj ->'; then
    shard=$i
  fi
done
[ -n "$shard" ] || fail "no shard holds stanford-bunny.obj"
job=$(submit "$work/resume" --array=0-3 --cpus-per-task=1)
until compgen -G "$work/resume/assets/stanford-bunny.builds/b-*" > /dev/null; do
  [ -n "$(squeue -h -j "${job}_$shard" 2> /dev/null)" ] || fail "task $shard ended before the bunny"
  sleep 0.05
done
scancel "${job}_$shard"
cluster_wait_job "$job"
echo "cancelled task $shard in the middle of stanford-bunny"
[ ! -e "$work/resume/assets/stanford-bunny.report.json" ] ||
  fail "the cancelled build published a report"
finished=$(wc -l < "$work/resume/assets/manifest-$shard-of-4.jsonl" || echo 0)
! "$gfield" batch --summary "$work/resume/assets" > "$work/summary.txt" 2>&1 ||
  fail "the summary of the cancelled array passes"
grep -q "rerun shards $shard of 4" "$work/summary.txt" || fail "the summary does not name shard $shard"

job=$(submit "$work/resume" --array="$shard" --export="ALL,GFIELD=$gfield,GFIELD_SHARDS=4")
cluster_wait_job "$job"
check_completed "$job"
resumed=$(tail -n +$((finished + 1)) "$work/resume/assets/manifest-$shard-of-4.jsonl")
[ "$(echo "$resumed" | grep -c '"status":"up to date"')" -eq "$finished" ] ||
  fail "the resubmitted task rebuilt what the cancelled one finished"
"$gfield" batch --summary "$work/resume/assets" > /dev/null || fail "the resumed summary fails"
for report in "$work"/resume/assets/*.report.json; do
  "$gfield" verify "${report%.report.json}" --rays 2000 > /dev/null ||
    fail "gfield verify ${report%.report.json} failed"
done
! compgen -G "$work/resume/assets/*.tmp-*" > /dev/null || fail "temporaries left behind"
! compgen -G "$work/resume/assets/*.builds/[bl]*" > /dev/null || fail "build folders left behind"
compare_assets "$work/single/assets" "$work/resume/assets"
