#!/usr/bin/env bash
# What in the model makes the coil reverse, or could make it disorder early? (results/paper/
# README.md, "What D counts"). Fig. 5b's scene (rho = 20, xi = 10, eps = 1e3, default numerics)
# with one thing changed, beside Fig. 5b's committed runs (twist on, the feeder holding the
# wire's spin, damping ratio 0.05, shell mesh 2 r). Each scene NAME_VARIANT.json:
#   notwist    numerics.twist = "off": no twist DOFs, no friction torque, no twist energy;
#   swivel     feeder_spin = "free": the wire may spin at the hole, so twist is not wound up
#              against the feeder;
#   lowdamp    numerics.damping_ratio = 0.01 (default 0.05): every dashpot a fifth as strong;
#   fineshell  numerics.shell_mesh_size = r (default 2 r): about 4x the shell's faces.
# mu_s = 0.75 (seeds 1, 2) and 1 (seed 1) go to l = 36 with snapshots every 6 l;
# fig4_mu_s-0.5_s1_swivel.json is Fig. 4's crumpling run (mu_s = 0.5, seed 1) with the swivel, to
# l = 100, snapshots every 10 l, beside the committed Fig. 4 run.
# Writes summary.csv: per run and snapshot, the order parameters and the sense blocks of
# `wirepack export --profile`, and U_t / U_b from the series row nearest the snapshot. The run
# files go to runs/ (not committed); a run already there is not run again. 5-10 min a run to
# l = 36 on one core (fineshell: ~4x), ~40 min to l = 100.
# Usage: bash results/paper/model_check/make.sh [WIREPACK]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
wp=${1:-$here/../../../build/wirepack}
mkdir -p "$here/runs"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "run,mu_s,seed,variant,l,D,D_chord,D_kappa,chord_R,reversals,order_length_R,Ut_over_Ub" \
  > "$tmp/summary.csv"
for scene in "$here"/*.json; do
  name=$(basename "$scene" .json)
  run=$here/runs/$name.h5
  [ -f "$run" ] || "$wp" run "$scene" --out "$run" > /dev/null
  mu=$(grep -o '"mu_s":[0-9.]*' "$scene" | cut -d: -f2)
  seed=$(grep -o '"seed":[0-9]*' "$scene" | cut -d: -f2)
  variant=${name##*_}
  "$wp" export "$run" --csv "$tmp/series.csv"
  k=1
  while "$wp" export "$run" --profile "$tmp/p.csv" --snapshot "$k" 2> /dev/null; do
    # "# ..., l = L", "# D = a, D_chord = b, D_kappa = c, entry chord = d R",
    # "# reversals = e, order length = f R"
    row=$(awk -v pre="$name,$mu,$seed,$variant" 'NR == 1 { sub(/.*l = /, ""); l = $0 }
      NR == 2 { gsub(/[#A-Za-z_=R ]/, ""); v = $0 }
      NR == 3 { gsub(/[#A-Za-z_=R ]/, ""); print pre "," l "," v "," $0; exit }' "$tmp/p.csv")
    # U_t / U_b from the series row nearest the snapshot's l.
    l=$(echo "$row" | cut -d, -f5)
    ratio=$(awk -F, -v l="$l" 'NR == 1 { for (c = 1; c <= NF; c++) col[$c] = c; next }
      { d = $1 - l; if (d < 0) d = -d
        if (best == "" || d < best) { best = d; r = $col["U_b"] > 0 ? $col["U_t"] / $col["U_b"] : 0 } }
      END { printf "%.4g", r }' "$tmp/series.csv")
    echo "$row,$ratio" >> "$tmp/summary.csv"
    k=$((k + 1))
  done
done
mv "$tmp/summary.csv" "$here/summary.csv"
column -s, -t "$here/summary.csv"
