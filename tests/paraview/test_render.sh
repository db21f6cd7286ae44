#!/usr/bin/env bash
# `wirepack render` with ParaView end to end (issue 18): two short runs, a rigid and an elastic
# one (rho = 10, to l = 3 and 4, snapshots every l = 1; the elastic shell stiff enough, eps = 10,
# that the wire bends along it), then
#   - a picture of each at the asked size (ffprobe), with the wire's colours in it: pixels of
#     strong saturation (max - min channel >= 100; the translucent shell and the grey sphere
#     stay below that) in the middle half of the picture (the colour bars are outside it), of
#     at least two hues of the kappa R map;
#   - the elastic one at half radius (its last snapshot named by --snapshot): fewer saturated
#     pixels than at full radius (a thinner tube), still of at least two hues;
#   - a movie of the elastic run: as many frames as the run file has snapshots (ffprobe);
#   - a layout 1 run file (tests/sweep/data/run_layout1.h5, no fields) still renders.
#   tests/paraview/test_render.sh WIREPACK_BINARY [SOURCE_DIR]   (ctest --test-dir build -L paraview)
# Exit 77 (ctest: skipped) when pvbatch, ffmpeg or ffprobe is missing (scripts/install_paraview.sh);
# WIREPACK_PARAVIEW_REQUIRED=1 (CI) fails instead.
set -euo pipefail

say() { echo "test_render: [${SECONDS} s] $*"; }
die() {
  echo "test_render: FAIL: $*" >&2
  exit 1
}
[ $# -ge 1 ] || {
  echo "usage: $0 WIREPACK_BINARY [SOURCE_DIR]" >&2
  exit 2
}
wirepack=$(realpath "$1")
src=$(realpath "${2:-$(dirname "$0")/../..}")
for cmd in pvbatch ffmpeg ffprobe; do
  if ! command -v "$cmd" >/dev/null; then
    [ "${WIREPACK_PARAVIEW_REQUIRED:-0}" = 1 ] && die "$cmd is not installed (scripts/install_paraview.sh)"
    say "SKIP: $cmd is not installed (scripts/install_paraview.sh installs ParaView and ffmpeg)"
    exit 77
  fi
done
[ -x "$wirepack" ] || die "$wirepack: no wirepack binary"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/wirepack-render.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"

# "W,H" of a picture or a movie's first stream.
size_of() { ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=p=0 "$1"; }

# Saturated pixels in the middle half (columns W/4 to 3W/4) of a W-pixel-wide PNG, by hue
# sextant: "total s0 s1 s2 s3 s4 s5" (red, yellow, green, cyan, blue, magenta).
hues() {
  ffmpeg -v error -i "$1" -f rawvideo -pix_fmt rgb24 - | python3 -c '
import colorsys, sys
w = int(sys.argv[1])
data = sys.stdin.buffer.read()
bins = [0] * 6
for i in range(0, len(data), 3):
    if not w // 4 <= (i // 3) % w < 3 * w // 4:
        continue
    r, g, b = data[i], data[i + 1], data[i + 2]
    if max(r, g, b) - min(r, g, b) >= 100:
        h = colorsys.rgb_to_hsv(r / 255, g / 255, b / 255)[0]
        bins[int(((h * 6) + 0.5) % 6)] += 1
print(sum(bins), *bins)' "$2"
}

# Checks a picture: W x H and the wire's colours (>= 300 saturated pixels, >= 2 hues of
# >= 20 pixels each); prints the saturated count.
check_picture() {
  local png=$1 w=$2 h=$3
  [ -s "$png" ] || die "$png was not written"
  [ "$(size_of "$png")" = "$w,$h" ] || die "$png is $(size_of "$png"), expected $w,$h"
  read -r total s0 s1 s2 s3 s4 s5 < <(hues "$png" "$w")
  local populated=0
  for s in $s0 $s1 $s2 $s3 $s4 $s5; do [ "$s" -ge 20 ] && populated=$((populated + 1)); done
  say "$png: $w x $h, $total saturated pixels (hues: $s0 $s1 $s2 $s3 $s4 $s5)" >&2
  [ "$total" -ge 300 ] || die "$png: only $total saturated pixels: no wire drawn"
  [ "$populated" -ge 2 ] || die "$png: the wire has fewer than 2 colours (hues $s0 $s1 $s2 $s3 $s4 $s5)"
  echo "$total"
}

say "runs"
echo '{"rho": 10, "shell": "rigid", "mu_s": 0, "l_max": 3, "output": {"snapshots_every_l": 1}}' > rigid.json
echo '{"rho": 10, "xi": 10, "eps": 10, "shell": "elastic", "mu_s": 0, "l_max": 4,
       "numerics": {"element_length": 1e-3, "shell_mesh_size": 1e-3},
       "output": {"snapshots_every_l": 1}}' > elastic.json
for kind in rigid elastic; do
  "$wirepack" run $kind.json --out $kind.h5 2> $kind.log >/dev/null || { cat $kind.log; die "$kind run failed"; }
done

snapshots=$(h5ls elastic.h5/snapshots | wc -l)
[ "$snapshots" -ge 3 ] || die "the elastic run has $snapshots snapshots, expected >= 3"

say "pictures"
"$wirepack" render rigid.h5 --out rigid.png --size 640x480 || die "render rigid.h5 failed"
check_picture rigid.png 640 480 >/dev/null
"$wirepack" render elastic.h5 --out elastic.png --size 640x480 || die "render elastic.h5 failed"
full=$(check_picture elastic.png 640 480)
"$wirepack" render elastic.h5 --out half.png --size 640x480 --half-radius --snapshot $((snapshots - 1)) ||
  die "render --half-radius failed"
half=$(check_picture half.png 640 480)
[ "$half" -lt "$full" ] || die "--half-radius: $half saturated pixels, not fewer than $full"
ls "$tmp" | grep -q 'tmp' && die "temporary files left: $(ls "$tmp")"

say "movie"
"$wirepack" render elastic.h5 --movie elastic.mp4 --size 320x240 || die "render --movie failed"
frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames \
  -of csv=p=0 elastic.mp4)
say "elastic.mp4: $frames frames, $snapshots snapshots, $(size_of elastic.mp4)"
[ "$frames" = "$snapshots" ] || die "elastic.mp4 has $frames frames for $snapshots snapshots"
[ "$(size_of elastic.mp4)" = "320,240" ] || die "elastic.mp4 is $(size_of elastic.mp4)"

say "a layout 1 run file (no fields)"
"$wirepack" render "$src/tests/sweep/data/run_layout1.h5" --out old.png --size 320x240 ||
  die "render of the layout 1 fixture failed"
[ "$(size_of old.png)" = "320,240" ] || die "old.png is $(size_of old.png)"
say "PASS"
