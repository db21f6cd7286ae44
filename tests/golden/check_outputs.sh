#!/usr/bin/env bash
# Byte-identical outputs (issue 17): `wirepack analyze` and `wirepack accuracy` on the committed
# sweep directory tests/golden/sweep must write exactly the committed files in
# tests/golden/expected: every CSV and gnuplot script byte for byte, every PNG by its SHA-256
# (checked only where gnuplot is installed). A change that is meant to alter an output regenerates
# them with WIREPACK_GOLDEN_UPDATE=1 and says why in its commit.
#
# The sweep: tests/golden/sweep/golden.sweep.json (rigid, rho = 10, l = 4, mu_s x tolerance,
# 2 seeds; made with `wirepack sweep golden.sweep.json --out sweep`, joblog and lock removed),
# plus an unreadable run file and a killed run's .part, so runs.csv lists both.
# Usage: check_outputs.sh WIREPACK SOURCE_DIR
set -euo pipefail
wirepack=$1
src=$2/tests/golden
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -r "$src/sweep" "$tmp/sweep"
cd "$tmp"
"$wirepack" analyze sweep --out out/analysis >/dev/null 2>analyze.log || {
  cat analyze.log
  exit 1
}
"$wirepack" accuracy sweep --window 1,4 --out out/accuracy >/dev/null 2>accuracy.log || {
  cat accuracy.log
  exit 1
}
# PNGs become checksums (one file per directory), so the comparison is one `diff -r`.
have_png=0
for d in out/analysis/plots out/accuracy; do
  if compgen -G "$d/*.png" >/dev/null; then
    have_png=1
    (cd "$d" && sha256sum ./*.png >png.sha256 && rm ./*.png)
  fi
done
if [ "${WIREPACK_GOLDEN_UPDATE:-0}" = 1 ]; then
  [ "$have_png" = 1 ] || { echo "update needs gnuplot (the PNG checksums)"; exit 1; }
  rm -rf "$src/expected"
  cp -r out "$src/expected"
  echo "updated $src/expected"
  exit 0
fi
exclude=()
if [ "$have_png" = 0 ]; then
  echo "gnuplot not found: PNG checksums not compared"
  exclude=(-x png.sha256)
fi
if ! diff -r "${exclude[@]}" "$src/expected" out; then
  echo "outputs differ from tests/golden/expected (see the diff above)"
  exit 1
fi
echo "analyze and accuracy outputs byte-identical to tests/golden/expected"
