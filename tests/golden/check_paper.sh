#!/usr/bin/env bash
# The paper reproduction's committed tables are what `wirepack analyze` makes from its committed
# run data (issue 15): for every figure of results/paper with run files and an analysis folder,
# the analysis is rerun into a temporary folder and every CSV compared byte for byte with the
# committed one. Exit 77 (skipped) while no figure has both yet.
# Usage: check_paper.sh WIREPACK SOURCE_DIR
set -euo pipefail
wirepack=$1
paper=$2/results/paper
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
checked=0
for dir in "$paper"/*/; do
  fig=$(basename "$dir")
  compgen -G "$dir/sweep/runs/*.h5" >/dev/null || continue
  [ -d "$dir/analysis" ] || continue
  cp -r "$dir/sweep" "$tmp/$fig"
  "$wirepack" analyze "$tmp/$fig" --out "$tmp/$fig.out" --no-plots >/dev/null 2>"$tmp/$fig.log" || {
    cat "$tmp/$fig.log"
    exit 1
  }
  for csv in "$dir"/analysis/*.csv; do
    if ! diff -q "$csv" "$tmp/$fig.out/$(basename "$csv")" >/dev/null; then
      diff "$csv" "$tmp/$fig.out/$(basename "$csv")" | head -20
      echo "results/paper/$fig/analysis/$(basename "$csv") is not what wirepack analyze makes" \
        "from results/paper/$fig/sweep: rerun bash results/paper/make.sh analyze $fig"
      exit 1
    fi
  done
  checked=$((checked + 1))
  echo "results/paper/$fig: analysis tables match the run data"
done
if [ "$checked" = 0 ]; then
  echo "no figure of results/paper has run data and tables yet"
  exit 77
fi
