#!/usr/bin/env bash
# Does the wire's twist make the coil reverse? (results/paper/README.md, "What D counts"). Fig. 5b's
# scene (rho = 20, xi = 10, eps = 1e3, default numerics) at mu_s = 0.75 (seeds 1, 2) and 1
# (seed 1), to l = 36, snapshots every 6 l, in two variants beside Fig. 5b's committed runs (twist
# on, the feeder holding the wire's spin):
#   NAME_notwist.json  numerics.twist = "off": no twist DOFs, no friction torque, no twist energy;
#   NAME_swivel.json   twist on, feeder_spin = "free": the wire may spin at the hole, so twist is
#                      not wound up against the feeder.
# Writes summary.csv (per run and snapshot: the order parameters and the sense blocks of
# `wirepack export --profile`); the run files go to runs/ (not committed). 10-20 min a run on one
# core.
# Usage: bash results/paper/twist_check/make.sh [WIREPACK]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
wp=${1:-$here/../../../build/wirepack}
mkdir -p "$here/runs"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "run,mu_s,seed,variant,l,D,D_chord,D_kappa,chord_R,reversals,order_length_R" > "$tmp/summary.csv"
for scene in "$here"/*_notwist.json "$here"/*_swivel.json; do
  name=$(basename "$scene" .json)
  run=$here/runs/$name.h5
  [ -f "$run" ] || "$wp" run "$scene" --out "$run" > /dev/null
  mu=$(grep -o '"mu_s":[0-9.]*' "$scene" | cut -d: -f2)
  seed=$(grep -o '"seed":[0-9]*' "$scene" | cut -d: -f2)
  variant=${name##*_}
  for k in 1 2 3 4 5 6; do
    "$wp" export "$run" --profile "$tmp/p.csv" --snapshot "$k"
    # "# ..., l = L", "# D = a, D_chord = b, D_kappa = c, entry chord = d R",
    # "# reversals = e, order length = f R"
    awk -v pre="$name,$mu,$seed,$variant" 'NR == 1 { sub(/.*l = /, ""); l = $0 }
      NR == 2 { gsub(/[#A-Za-z_=R ]/, ""); v = $0 }
      NR == 3 { gsub(/[#A-Za-z_=R ]/, ""); print pre "," l "," v "," $0; exit }' \
      "$tmp/p.csv" >> "$tmp/summary.csv"
  done
done
mv "$tmp/summary.csv" "$here/summary.csv"
column -s, -t "$here/summary.csv"
