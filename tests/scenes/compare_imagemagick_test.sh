#!/usr/bin/env bash
# CTest: `gfield compare` of two PNGs gives ImageMagick's PSNR of the same files (within 0.1 dB;
# ImageMagick's `compare -metric PSNR`, on the stored 8-bit values), for renders of an example
# scene at two sample counts and for a pair ImageMagick generates itself (a grey ramp and a noisy
# copy, seeded), and the same pair as JPEG. On the renders, whose errors lie in the dark tones,
# a gfield compare on linear light (--linear) differs from it by more than 0.5 dB.
# Usage: compare_imagemagick_test.sh GFIELD DATA_DIR
set -euo pipefail
gfield=$1
data=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v compare > /dev/null || { echo "ImageMagick's compare is missing (scripts/install-deps.sh)"; exit 1; }

scene=$data/scenes/mirror-torus-instances.json
"$gfield" render "$scene" --size 64x48 --spp 1 -q -o "$work/one.png"
"$gfield" render "$scene" --size 64x48 --spp 4 -q -o "$work/four.png"
convert -size 64x48 gradient:gray20-gray80 -colorspace sRGB -type TrueColor -depth 8 "$work/ramp.png"
convert "$work/ramp.png" -seed 7 -attenuate 0.3 +noise Gaussian -type TrueColor -depth 8 "$work/noisy.png"
convert "$work/ramp.png" -quality 95 "$work/ramp.jpg"
convert "$work/noisy.png" -quality 95 "$work/noisy.jpg"

failed=0
check() {
  local a=$1 b=$2 min_linear_gap=$3 ours theirs linear
  ours=$("$gfield" compare "$a" "$b" | sed -n 's/^PSNR *\([0-9.]*\) dB$/\1/p')
  theirs=$(compare -metric PSNR "$a" "$b" null: 2>&1 || true)
  linear=$("$gfield" compare "$a" "$b" --linear | sed -n 's/^PSNR *\([0-9.]*\) dB$/\1/p')
  echo "$(basename "$a") vs $(basename "$b"): gfield $ours dB, ImageMagick $theirs dB," \
    "gfield --linear $linear dB"
  if ! awk -v o="$ours" -v t="$theirs" -v l="$linear" -v g="$min_linear_gap" \
      'BEGIN { d = o - t; if (d < 0) d = -d; e = o - l; if (e < 0) e = -e;
               exit !(o != "" && l != "" && t + 0 > 0 && d <= 0.1 && e >= g) }'; then
    echo "FAIL: gfield's PSNR is not ImageMagick's within 0.1 dB" \
      "(or --linear is not $min_linear_gap dB or more away)"
    failed=1
  fi
}
check "$work/one.png" "$work/four.png" 0.5
check "$work/ramp.png" "$work/noisy.png" 0
check "$work/ramp.jpg" "$work/noisy.jpg" 0
exit $failed
