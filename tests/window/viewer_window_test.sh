#!/usr/bin/env bash
# CTest: the interactive gfield-view as a person meets it. A real window under Xvfb (GLX on
# Mesa's llvmpipe) is driven with synthetic key and mouse events (xdotool) and its pixels are
# read back from the X server (ImageMagick's import), never from the viewer itself. After each
# method switch (key m, starting from --method cubemap: the methods that cannot draw the scene
# are skipped), after an orbit (a mouse drag), after a method chosen for the right half from the
# panel's drop-down, and after a screenshot (key p), the window's picture must match
# gfield-view --headless rendering the same state (PSNR >= 40 dB, gfield compare). The
# screenshot's command line (stdout) is that headless command; screenshots are numbered after
# the last one in the folder.
# Usage: viewer_window_test.sh GFIELD GFIELD_VIEW DATA_DIR
set -euo pipefail
gfield=$1
view=$2
data=$3
for tool in Xvfb xdotool import; do
  command -v "$tool" > /dev/null || { echo "viewer_window_test: $tool is not installed" >&2; exit 1; }
done
work=$(mktemp -d "${TMPDIR:-/tmp}/gfield-window-test.XXXXXX")
xvfb_pid=""
viewer_pid=""
cleanup() {
  [ -z "$viewer_pid" ] || kill "$viewer_pid" 2> /dev/null || true
  [ -z "$xvfb_pid" ] || kill "$xvfb_pid" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

# A scene on which every method but glass draws a picture of its own (a water sphere and a glass
# teapot: wyman2005 and davis-wyman need the teapot's thickness map).
scene=$data/scenes/hurley-water-glass.json
size=256
min_psnr=40
"$gfield" build "$data/meshes/teapot.obj" -o "$work/assets/teapot" --size 128 --samples 8 \
  --verify-rays 0 > /dev/null
"$gfield" thickness "$work/assets/teapot" > /dev/null

# An X server of our own on a free display (Xvfb writes the display's number when it is ready).
# -noreset: by default the server resets whenever its last client leaves (here each xdotool and
# import call), and a client connecting during the reset is refused.
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp -noreset 3> "$work/display" \
  2> "$work/xvfb.log" &
xvfb_pid=$!
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || { cat "$work/xvfb.log" >&2; echo "Xvfb did not start" >&2; exit 1; }
export DISPLAY=":$(cat "$work/display")"

mkdir "$work/shots"
cp "$data/meshes/spot-painted.png" "$work/shots/gfield-view-7.png"  # screenshots come after it
(cd "$work/shots" && exec "$view" "$scene" --assets "$work/assets" --size ${size}x${size} \
  --method cubemap > "$work/viewer.log" 2>&1) &
viewer_pid=$!
window=""
for _ in $(seq 300); do
  window=$(xdotool search --onlyvisible --name '^gfield-view' 2> /dev/null | head -n 1) &&
    [ -n "$window" ] && break
  kill -0 "$viewer_pid" 2> /dev/null || { cat "$work/viewer.log" "$work/xvfb.log" >&2; exit 1; }
  sleep 0.2
done
[ -n "$window" ] || { echo "no gfield-view window" >&2; exit 1; }
eval "$(xdotool getwindowgeometry --shell "$window")"  # X, Y, WIDTH, HEIGHT
for _ in $(seq 50); do xdotool windowfocus "$window" 2> /dev/null && break; sleep 0.2; done

# headless OUT ARGS...: the same scene and size rendered without a window. Under the sanitizers
# without LeakSanitizer, whose stop-the-world tracer crashed at the exit of a davis-wyman render
# beside other tests (google/sanitizers#1353; the headless renders' leaks are the other tests'
# business, the window's are this one's).
headless() {
  local out=$1
  shift
  ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
    "$view" "$scene" --assets "$work/assets" --headless --size ${size}x${size} "$@" -o "$out"
}
psnr() { "$gfield" compare "$1" "$2" | awk '$1 == "PSNR" { print $2 }'; }
# wait_for NAME EXPECTED.png [LEFT WIDTH]: the window's picture (or its columns LEFT..LEFT+WIDTH)
# matches EXPECTED's same columns within 60 s; the picture is redrawn only after the events.
wait_for() {
  local name=$1 expected=$2 left=${3:-0} width=${4:-$size} value=0
  convert "$expected" -crop "${width}x${size}+${left}+0" +repage "$work/$name-expected.png"
  for _ in $(seq 120); do
    import -window root -crop "${width}x${size}+$((X + left))+${Y}" +repage "$work/$name-window.png"
    value=$(psnr "$work/$name-window.png" "$work/$name-expected.png")
    if awk -v v="$value" -v m=$min_psnr 'BEGIN { exit !(v == "inf" || v >= m) }'; then
      echo "window test: $name: PSNR $value dB against the headless render"
      return 0
    fi
    sleep 0.5
  done
  echo "window test: $name: the window's picture is $value dB from the headless render" \
    "(< $min_psnr) after 60 s; viewer log:" >&2
  cat "$work/viewer.log" >&2
  mkdir -p window-test-failure && cp "$work/$name-"*.png window-test-failure/
  exit 1
}

# The method order is the registry's (--help); methods that cannot draw the scene are skipped.
methods=$("$view" --help | sed -n 's/.*--method TEXT:{\([^}]*\)}.*/\1/p' | tr ',' ' ')
drawable=()
for m in $methods; do
  if headless "$work/expected-$m.png" --method "$m" 2> "$work/expected-$m.log"; then
    drawable+=("$m")
  fi
done
if [ "${#drawable[@]}" -lt 5 ]; then
  echo "only ${#drawable[*]} methods draw the scene (${drawable[*]}); the others said:" >&2
  for m in $methods; do
    [[ " ${drawable[*]} " == *" $m "* ]] || sed "s/^/  $m: /" "$work/expected-$m.log" >&2
  done
  exit 1
fi
start=0
for k in "${!drawable[@]}"; do [ "${drawable[$k]}" != cubemap ] || start=$k; done
count=${#drawable[@]}
for k in "${!drawable[@]}"; do  # a switch that shows nothing new would go unseen
  a=${drawable[$k]} b=${drawable[$(((k + 1) % count))]}
  value=$(psnr "$work/expected-$a.png" "$work/expected-$b.png")
  awk -v v="$value" 'BEGIN { exit !(v != "inf" && v < 30) }' ||
    { echo "$a and $b draw the same picture ($value dB): choose another scene" >&2; exit 1; }
done
for step in $(seq 0 "$count"); do  # round the registry once, back to where it started
  m=${drawable[$(((start + step) % count))]}
  [ "$step" -eq 0 ] || xdotool key m
  wait_for "method-$step-$m" "$work/expected-$m.png"
done

# Screenshots (key p) before and after an orbit (a left drag) on the geometry-field method:
# gfield-view-8.png and -9.png and, on stdout, the headless command of each picture; after the
# drag, that command's picture and the screenshot must match the window.
for _ in $(seq $((count - start))); do xdotool key m; done  # from cubemap round to field
wait_for "back-to-field" "$work/expected-field.png"
screenshot() {  # screenshot N: key p, then the viewer's line for gfield-view-N.png
  xdotool key p
  for _ in $(seq 100); do grep -q "saved gfield-view-$1.png" "$work/viewer.log" && break; sleep 0.2; done
  grep -m 1 "saved gfield-view-$1.png; headless: " "$work/viewer.log" ||
    { cat "$work/viewer.log" >&2; echo "no screenshot gfield-view-$1.png" >&2; exit 1; }
}
camera_of() { sed 's/.*--camera \([^ ]*\).*/\1/' <<< "$1"; }
line=$(screenshot 8)
before=$(camera_of "$line")
xdotool mousemove --window "$window" 128 128 mousedown 1 mousemove --window "$window" 168 118 \
  mouseup 1
line=$(screenshot 9)
camera=$(camera_of "$line")
[ "$camera" != "$before" ] || { echo "the drag did not orbit: $line" >&2; exit 1; }
command=${line#*headless: gfield-view }
read -r -a words <<< "${command% -o *}"
"$view" "${words[@]}" -o "$work/orbit-expected.png"
wait_for "orbit" "$work/orbit-expected.png"
value=$(psnr "$work/shots/gfield-view-9.png" "$work/orbit-window.png")
echo "window test: the screenshot is $value dB from the window"
awk -v v="$value" -v m=$min_psnr 'BEGIN { exit !(v == "inf" || v >= m) }'

# The right half from the panel's drop-down, by mouse: the "right half" combo is the panel's
# second row and its list starts with "(off)", one row per method in the registry's order. With
# Dear ImGui's default style (13 px font, 3 px frame padding, 4 px item spacing, 8 px window
# padding, 19 px title bar) the combo's centre is 59 px from the window's top and the list's
# k-th row (0: off) 84 + 17k px.
row=0
for m in $methods; do row=$((row + 1)); [ "$m" != cubemap ] || break; done
xdotool mousemove --window "$window" $((size + 150)) 59 click 1
sleep 1
xdotool mousemove --window "$window" $((size + 150)) $((84 + 17 * row)) click 1
headless "$work/orbit-cubemap.png" --method cubemap --camera "$camera"
wait_for "right-half-field" "$work/orbit-expected.png" 0 $((size / 2))
wait_for "right-half-cubemap" "$work/orbit-cubemap.png" $((size / 2)) $((size / 2))

# The screenshot of a split picture names the right half's method; esc quits with exit code 0.
screenshot 10 | grep -q 'right half: --method cubemap'
xdotool key Escape
for _ in $(seq 100); do kill -0 "$viewer_pid" 2> /dev/null || break; sleep 0.2; done
wait "$viewer_pid" || { cat "$work/viewer.log" >&2; echo "gfield-view exited non-zero" >&2; exit 1; }
viewer_pid=""
echo "window test: passed (${drawable[*]})"
