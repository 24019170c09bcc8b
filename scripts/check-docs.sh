#!/usr/bin/env bash
# The docs test (CI runs it after scripts/demo.sh and scripts/test.sh): runs the command blocks
# of README.md and docs/*.md that are marked runnable, as a new user would, in a fresh clone, and
# checks the figures that README.md and docs quote against what their commands print today.
#
# Markers (docs/reliability.md, "The docs test"), each an HTML comment that Markdown does not show,
# at the start of its line:
#   <!-- check-docs: run -->           on the line before a ```sh fence: the block is run;
#   <!-- check-docs: skip REASON -->   on the line before a ```sh fence: not run (needs a display,
#                                      root, a cluster, ...); REASON says why and what covers it;
#   <!-- check-docs: figure VALUE ±NOISE "REGEX" COMMAND -->
#                                      in (or right after) a paragraph that quotes VALUE: after the
#                                      blocks, COMMAND runs in the clone's root; the first match of
#                                      the extended regular expression REGEX in its output (its
#                                      group 1) must be within NOISE of VALUE, and VALUE must
#                                      appear in the paragraph's text.
# Every ```sh block needs a run or skip marker. In README.md, a paragraph that quotes a command
# (`build/...`, `scripts/...`, `gfield ...`, `bench_...`, `cmake`, `cpack`) and a figure (a number
# with dB, s, ms, MB, GB, min, %, × or Mrays/s) must hold a figure marker or a date (YYYY-MM-DD):
# a measurement too expensive to repeat here says when it was taken.
#
# The clone: the checkout's tracked and untracked, not ignored files (what .ci/run copies; in a
# folder that is no git checkout: every file git would not ignore there) copied into an empty
# temporary folder, made a git repository of one commit, so that `git status --porcelain` shows
# whatever the commands leave outside the ignored folders (it must be empty after the set-up and
# after the blocks). The clone's build/ is a symbolic link to the checkout's build folder (already
# built with its tests: scripts/test.sh, as in CI), so nothing is compiled: the tools found
# there read their shaders from the checkout's shaders/ (the path compiled into gfield-view) and
# run `gfield assets` from beside themselves, the same files as the clone's. The set-up is the
# README's first command without its package check and build, `scripts/demo.sh --no-build` (out/:
# spot's and the torus's assets, the mirror-torus pictures); the README's second command, the
# test suite, writes only under build/ and is not repeated. Then the blocks run in file order
# (README.md, then docs/*.md by name), each as its own `bash` with set -euo pipefail in the
# clone's root. A failing block prints the file, the block's first line, the commands and their
# output, and the script goes on with the next block; it exits 1 if anything failed.
# Usage: scripts/check-docs.sh [--keep] [FILE.md...]   (FILE.md: only these files' blocks and
# figures; --keep: leave the clone in place and print where)
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD
keep=0
if [ "${1:-}" = "--keep" ]; then
  keep=1
  shift
fi
if [ $# -gt 0 ]; then
  files=("$@")
else
  files=(README.md docs/*.md)
fi
for f in "${files[@]}"; do
  [ -f "$f" ] || { echo "check-docs: $f: no such file" >&2; exit 2; }
done
for tool in build/preprocess/gfield build/runtime/gfield-view; do
  [ -x "$tool" ] || { echo "check-docs: $tool is not built (scripts/build.sh)" >&2; exit 2; }
done

start=$SECONDS
failures=0
fail() {
  echo "check-docs: FAILED: $*"
  failures=$((failures + 1))
}

work=$(mktemp -d "${TMPDIR:-/tmp}/gfield-docs.XXXXXX")
if [ "$keep" = 1 ]; then
  trap 'echo "check-docs: the clone is kept in $work/gfield"' EXIT
else
  trap 'rm -rf "$work"' EXIT
fi
clone=$work/gfield
mkdir "$clone"
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  list=(git ls-files -z --cached --others --exclude-standard)
else
  git init -q "$work/index"
  list=(git --git-dir="$work/index/.git" --work-tree="$source_dir" ls-files -z --others
    --exclude-standard)
fi
"${list[@]}" | while IFS= read -r -d '' f; do if [ -e "$f" ]; then printf '%s\0' "$f"; fi; done |
  tar -cf - --null -T - | tar -xf - -C "$clone"
ln -s "$source_dir/build" "$clone/build"
(
  cd "$clone"
  git init -q
  echo /build >> .git/info/exclude  # the link to the checkout's build folder
  git add -A
  git -c user.name=check-docs -c user.email=check-docs@localhost commit -q -m "fresh clone"
)
echo "check-docs: clone of $source_dir in $clone ($(cd "$clone" && git ls-files | wc -l) files)"

# Files the commands left that git neither tracks nor ignores.
check_clean() {
  local left
  left=$(cd "$clone" && git status --porcelain)
  if [ -n "$left" ]; then
    fail "after $1, files that are neither tracked nor ignored:"
    echo "$left"
  fi
}

echo "== set-up: scripts/demo.sh --no-build"
t=$SECONDS
if (cd "$clone" && scripts/demo.sh --no-build) < /dev/null > "$work/setup.log" 2>&1; then
  echo "check-docs: set-up ok ($((SECONDS - t)) s)"
else
  cat "$work/setup.log"
  fail "set-up: scripts/demo.sh --no-build"
fi
check_clean "the set-up"

# Extracts the blocks of one file: each runnable one to blocks/NNN.sh (first line: its line
# number); a ```sh block without a marker is reported on stderr (exit 3).
extract_blocks() {
  awk -v out="$2" -v name="$1" '
    function flush() { if (cur != "") close(cur); cur = "" }
    inblock {
      if ($0 ~ /^[ \t]*```[ \t]*$/) { inblock = 0; flush(); prev = ""; next }
      if (cur != "") print $0 > cur
      next
    }
    /^[ \t]*```/ {
      lang = $0; sub(/^[ \t]*```/, "", lang); gsub(/[ \t]/, "", lang)
      inblock = 1
      if (lang == "sh" || lang == "bash" || lang == "shell") {
        if (prev ~ /^<!-- check-docs: run -->/) {
          n++; cur = sprintf("%s/%03d.sh", out, n); print NR + 1 > cur
        } else if (prev !~ /^<!-- check-docs: skip [^ ]/) {
          printf "%s:%d: a ```%s block without <!-- check-docs: run --> or <!-- check-docs: skip REASON --> on the line before\n", name, NR, lang > "/dev/stderr"
          bad = 1
        }
      }
      next
    }
    { prev = $0 }
    END { flush(); if (inblock) { printf "%s: a code block is not closed\n", name > "/dev/stderr"; bad = 1 } exit bad ? 3 : 0 }
  ' "$1"
}

for f in "${files[@]}"; do
  blocks=$work/blocks/${f//\//_}
  mkdir -p "$blocks"
  if ! extract_blocks "$f" "$blocks"; then
    fail "$f: unmarked sh blocks (above)"
  fi
  for b in "$blocks"/*.sh; do
    [ -e "$b" ] || continue
    line=$(head -n 1 "$b")
    script=$work/block.sh
    { echo "set -euo pipefail"; tail -n +2 "$b"; } > "$script"
    t=$SECONDS
    if (cd "$clone" && timeout "${GFIELD_DOCS_BLOCK_TIMEOUT:-600}" bash "$script") \
      < /dev/null > "$work/block.log" 2>&1; then
      echo "check-docs: $f:$line: ok ($((SECONDS - t)) s)"
    else
      rc=$?
      fail "$f:$line: the block exited $rc after $((SECONDS - t)) s:"
      tail -n +2 "$b" | sed 's/^/  $ /'
      echo "  output:"
      sed 's/^/  | /' "$work/block.log"
    fi
  done
done
check_clean "the blocks"

# The figure markers: VALUE ±NOISE "REGEX" COMMAND.
figure_re='^<!-- check-docs: figure ([0-9][0-9.]*) ±([0-9.]+) "([^"]+)" (.+) -->$'
for f in "${files[@]}"; do
  while IFS=: read -r line text; do
    if ! [[ $text =~ $figure_re ]]; then
      fail "$f:$line: a figure marker not of the form <!-- check-docs: figure VALUE ±NOISE \"REGEX\" COMMAND -->"
      continue
    fi
    value=${BASH_REMATCH[1]} noise=${BASH_REMATCH[2]} regex=${BASH_REMATCH[3]}
    command=${BASH_REMATCH[4]}
    # The paragraph around the marker (non-blank lines), without the markers.
    paragraph=$(awk -v n="$line" '
      /^[ \t]*$/ { if (NR < n) { buf = "" } else if (NR > n) { exit } ; next }
      { buf = buf "\n" $0 }
      END { print buf }' "$f" | grep -v '^<!-- check-docs:' || true)
    if ! grep -qF -- "$value" <<< "$paragraph"; then
      fail "$f:$line: the paragraph does not quote the figure $value"
      continue
    fi
    output=$(cd "$clone" && bash -c "$command" < /dev/null 2>&1) || {
      fail "$f:$line: $command exited $?: $output"
      continue
    }
    if ! [[ $output =~ $regex ]]; then
      fail "$f:$line: \"$regex\" not in the output of $command: $output"
      continue
    fi
    now=${BASH_REMATCH[1]}
    if awk -v a="$now" -v b="$value" -v t="$noise" 'BEGIN { d = a - b; exit !(d <= t && -d <= t) }'; then
      echo "check-docs: $f:$line: figure $value ±$noise: $now now"
    else
      fail "$f:$line: the text says $value ±$noise, but $command prints $now"
    fi
  done < <(grep -n '^<!-- check-docs: figure' "$f" || true)
done

# README.md: a paragraph quoting a command and a figure holds a figure marker or a date.
for f in "${files[@]}"; do
  [ "$f" = README.md ] || continue
  undated=$(awk '
    function check() {
      if (para != "" && para ~ cmd && (para ~ fig1 || para ~ fig2) && para !~ ok) print first
      para = ""
    }
    BEGIN {
      cmd = "`(build/|scripts/|gfield|bench_|cmake |cpack )"
      fig1 = "[0-9]( |\302\240)?(dB|ms|MB|GB|min|Mrays/s|s)([^A-Za-z0-9]|$)"
      fig2 = "[0-9]( |\302\240)?(%|\303\227)"
      ok = "check-docs: figure|20[0-9][0-9]-[01][0-9]-[0-3][0-9]"
    }
    /^[ \t]*```/ { check(); fence = !fence; next }
    fence { next }
    /^[ \t]*$/ { check(); next }
    { if (para == "") first = NR; para = para " " $0 }
    END { check() }' "$f")
  for line in $undated; do
    fail "$f:$line: a paragraph quotes a command and a figure, but neither a figure marker (<!-- check-docs: figure ... -->) nor the date of the measurement (YYYY-MM-DD)"
  done
done

if [ "$failures" -gt 0 ]; then
  echo "check-docs: $failures failure(s) in $((SECONDS - start)) s"
  exit 1
fi
echo "check-docs: ok in $((SECONDS - start)) s"
