#!/usr/bin/env bash
# How Fig. 4's and Fig. 6's numbers move along the packed length l, from the committed run data
# (after scripts/setup.sh; runs no simulation, ~20 s):
#   bash results/paper/fig4/along_l.sh [WIREPACK [OUT]]
# writes into OUT (default results/paper/fig4/along_l), and prints,
#   distributions_vs_l.csv  Fig. 6's lognormal fits of ln(kappa^2/<kappa^2>) and ln(Lambda/r) at
#                           every snapshot (`wirepack analyze --at-l L`), not only the last
#   morphology_vs_l.csv     each run's D, D_chord and sense blocks (reversals, order length) at
#                           every snapshot (analysis/morphology.csv at each l)
#   exponents_by_octave.csv every exponent fitted over each octave of l, [l_max/2^(k+1),
#                           l_max/2^k] for k = 0..3 (`--fit-window`, the scaling-window rule
#                           off): the local exponent, beside the whole window's in
#                           analysis/exponents.csv
#   phase_by_octave.csv     each run's order parameter over the same octaves (`--d-window`): the
#                           mean and the maximum of D and the maximum of D_chord, i.e. whether the
#                           packing is coiled or crumpled where each local exponent is taken
# Columns as in analysis/distributions.csv (without the histogram) and analysis/exponents.csv.
# WIREPACK defaults to build/wirepack. tests/golden/check_paper.sh reruns this script and
# compares its tables with the committed ones.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
wp=${1:-$here/../../../build/wirepack}
out=${2:-$here/along_l}
sweep=$here/sweep
[ -d "$sweep/runs" ] || { echo "along_l.sh: no run data in $sweep" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# analyze_into NAME FIT_AUTO ARGS...: the runs analysed into $tmp/NAME with the sweep's analysis
# settings, "fit_auto" set to FIT_AUTO (true or false), and the command-line ARGS.
analyze_into() {
  local d=$tmp/$1 fit_auto=$2
  shift 2
  mkdir -p "$d/runs"
  for f in "$sweep"/runs/*.h5; do ln -s "$f" "$d/runs/"; done
  cp "$sweep/joblog.csv" "$d/" 2> /dev/null || true
  sed "s/\"fit_auto\": \(true\|false\)/\"fit_auto\": $fit_auto/" "$sweep/manifest.json" \
    > "$d/manifest.json"
  "$wp" analyze "$d" --out "$d/analysis" --no-plots "$@" > "$d/log" 2>&1 ||
    { cat "$d/log" >&2; exit 1; }
}

# pick FILE COLUMNS CONDITION: the named columns (comma-separated) of FILE's rows for which the
# awk CONDITION (on $c["column"]) holds; no header.
pick() {
  awk -F, -v OFS=, -v want="$2" '
    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; n = split(want, w, ","); next }
    '"$3"' { for (i = 1; i <= n; i++) printf "%s%s", $c[w[i]], (i < n ? OFS : "\n") }' "$1"
}

# table FILE HEADER SORT: HEADER and the sorted $tmp/rows into FILE, written whole or not at all.
table() {
  { echo "$2"; sort -t, $3 "$tmp/rows"; } > "$tmp/table.csv"
  mv "$tmp/table.csv" "$out/$1"
  cat "$out/$1"
  echo
}

key() { grep -o "\"$1\": *[0-9.eE+-]*" "$here/fig4.sweep.json" | head -1 | grep -o '[0-9.eE+-]*$'; }
every=$(key snapshots_every_l)
lmax=$(key l_max)
mkdir -p "$out"

# Fig. 6's distributions at every snapshot l = every, 2 every, ..., l_max (the histogram's first
# bin carries the fits).
cols=mu_s,quantity,l,n_runs,n,mu,mu_stderr,sigma,sigma_stderr,mu_ls,sigma_ls
: > "$tmp/rows"
for l in $(awk -v e="$every" -v m="$lmax" 'BEGIN { for (k = 1; k * e <= m + 1e-9; k++) print k * e }'); do
  analyze_into "at$l" true --at-l "$l"
  pick "$tmp/at$l/analysis/distributions.csv" "$cols" '$c["bin"] == 0 && $c["ok"] == "true"' \
    >> "$tmp/rows"
done
table distributions_vs_l.csv "$cols" "-k1,1g -k2,2 -k3,3g"

# Each run's order parameters and sense blocks at the same snapshots: where the packing is a coil,
# a coil wound one way and then the other, or loops turning every way.
cols=mu_s,seed,l,D,D_chord,chord_R,reversals,order_length_R
: > "$tmp/rows"
for l in $(awk -v e="$every" -v m="$lmax" 'BEGIN { for (k = 1; k * e <= m + 1e-9; k++) print k * e }'); do
  pick "$tmp/at$l/analysis/morphology.csv" "$cols" '1' >> "$tmp/rows"
done
table morphology_vs_l.csv "$cols" "-k1,1g -k2,2g -k3,3g"

# Every exponent over each octave of l, plain least squares on log-spaced points, and each run's
# D over the same octave.
octaves="3 2 1 0"
for k in $octaves; do
  read -r lo hi < <(awk -v m="$lmax" -v k="$k" 'BEGIN { print m / 2 ^ (k + 1), m / 2 ^ k }')
  analyze_into "octave$k" false --fit-window "$lo,$hi" --d-window "$lo,$hi"
done
cols=mu_s,name,series,window_l_min,window_l_max,value,stderr,n_points,n_seeds,method
: > "$tmp/rows"
for k in $octaves; do
  pick "$tmp/octave$k/analysis/exponents.csv" "$cols" '$c["ok"] == "true"' >> "$tmp/rows"
done
if grep -q ',auto' "$tmp/rows"; then
  echo "along_l.sh: the octave fits still used the scaling-window rule" >&2
  exit 1
fi
table exponents_by_octave.csv "$cols" "-k1,1g -k2,2 -k4,4g"

cols=mu_s,seed,D_l_min,D_l_max,D_avg,D,D_chord
: > "$tmp/rows"
for k in $octaves; do
  pick "$tmp/octave$k/analysis/runs.csv" "$cols" '$c["status"] == "complete"' >> "$tmp/rows"
done
table phase_by_octave.csv "$cols" "-k1,1g -k2,2g -k3,3g"
