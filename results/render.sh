#!/usr/bin/env bash
# Renders one snapshot of a run file to PNG with gnuplot: the wire as a tube-like line and,
# for an elastic shell, the shell as a wireframe, seen from the side and from above.
# Usage: results/render.sh RUN.h5 OUT.png [SNAPSHOT_INDEX (default: the last)] [TITLE]
# Needs h5dump (Debian package hdf5-tools, installed by scripts/setup.sh) and gnuplot.
set -euo pipefail
run=$1 out=$2
k=${3:-$(h5ls "$run/snapshots" | awk '{print $1}' | sort -n | tail -1)}
title=${4:-$(basename "$run")}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
dump() { h5dump -d "$1" -y -w 0 -o "$2" "$run" > /dev/null 2>&1 || : > "$2"; }
dump "/snapshots/$k/wire" "$tmp/wire.raw"
dump "/snapshots/$k/shell_vertices" "$tmp/sv.raw"
dump "/snapshots/$k/shell_triangles" "$tmp/st.raw"
l=$(h5dump -a "/snapshots/$k/l" "$run" 2>/dev/null | awk '/\(0\)/{print $2}')
# One number per token; regroup by 3.
tr -s ', \n' '\n' < "$tmp/wire.raw" | grep -v '^$' | paste - - - > "$tmp/wire.dat"
if [ -s "$tmp/sv.raw" ]; then
  tr -s ', \n' '\n' < "$tmp/sv.raw" | grep -v '^$' | paste - - - > "$tmp/sv.dat"
  tr -s ', \n' '\n' < "$tmp/st.raw" | grep -v '^$' | paste - - - > "$tmp/st.dat"
  # Each triangle as a closed polyline block (for the wireframe).
  awk 'NR==FNR {v[NR-1]=$0; next} {print v[$1]; print v[$2]; print v[$3]; print v[$1]; print ""}' \
    "$tmp/sv.dat" "$tmp/st.dat" > "$tmp/shell.dat"
else
  : > "$tmp/shell.dat"
fi
gnuplot <<GP
set terminal pngcairo size 1200,600 font ",11"
set output "$out"
set multiplot layout 1,2 title sprintf("%s, l = %.1f", "$title", ${l:-0})
unset key; unset border; unset tics; set view equal xyz
set view 80,20
splot "$tmp/shell.dat" using 1:2:3 with lines lc rgb "#b0b0b0" lw 0.5, \
      "$tmp/wire.dat" using 1:2:3 with lines lc rgb "#c03020" lw 2.5
set view 0,0
splot "$tmp/shell.dat" using 1:2:3 with lines lc rgb "#b0b0b0" lw 0.5, \
      "$tmp/wire.dat" using 1:2:3 with lines lc rgb "#c03020" lw 2.5
unset multiplot
GP
echo "$out"
