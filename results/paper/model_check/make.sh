#!/usr/bin/env bash
# What in the model makes the coil reverse, or could make it disorder early? (results/paper/
# README.md, "What D counts"). Fig. 5b's scene (rho = 20, xi = 10, eps = 1e3, default numerics)
# with one thing changed, beside Fig. 5b's committed runs (twist on, the feeder holding the
# wire's spin, damping ratio 0.05, shell mesh 2 r). Each scene NAME_VARIANT.json:
#   notwist    numerics.twist = "off": no twist DOFs, no friction torque, no twist energy;
#   swivel     feeder_spin = "free": the wire may spin at the hole, so twist is not wound up
#              against the feeder;
#   lowdamp    numerics.damping_ratio = 0.01 (default 0.05): every dashpot a fifth as strong;
#   fineshell  numerics.shell_mesh_size = r (default 2 r): about 4x the shell's faces;
#   softstick  friction_stiffness_ratio = 0.2 (Mindlin's 0.8 / 4): a sticking contact creeps
#              4x further before it slips;
#   stiffstick friction_stiffness_ratio = 3.2 (4x Mindlin's): nearer an ideal Coulomb stick;
#   control    nothing changed: reproduces Fig. 5b's committed run bitwise up to l = 36 (the
#              output settings and l_max do not move the physics).
# mu_s = 0.75 (seeds 1, 2) and 1 (seed 1) go to l = 36 with snapshots every 6 l;
# fig4_mu_s-0.5_s1_swivel.json is Fig. 4's crumpling run (mu_s = 0.5, seed 1) with the swivel, to
# l = 100, snapshots every 10 l, beside the committed Fig. 4 run.
# Writes summary.csv: per run and snapshot, the order parameters and the sense blocks of
# `wirepack export --profile`, and U_t / U_b from the series row nearest the snapshot. The run
# files go to runs/ (not committed); a run already there is not run again. 10-20 min a run to
# l = 36 on one core (fineshell: ~4x), ~50 min to l = 100.
# Usage: bash results/paper/model_check/make.sh [WIREPACK [NAME ...]]
# With NAMEs (scene names without .json) only those run, and only their rows of summary.csv are
# remade; the other rows are kept (their run files need not be here).
set -euo pipefail
export LC_ALL=C
here=$(cd "$(dirname "$0")" && pwd)
wp=${1:-$here/../../../build/wirepack}
shift || true
names=("$@")
if [ ${#names[@]} = 0 ]; then
  for scene in "$here"/*.json; do names+=("$(basename "$scene" .json)"); done
fi
for name in "${names[@]}"; do
  [ -f "$here/$name.json" ] || { echo "make.sh: no scene $here/$name.json" >&2; exit 2; }
done
mkdir -p "$here/runs"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "run,mu_s,seed,variant,l,D,D_chord,D_kappa,chord_R,reversals,order_length_R,Ut_over_Ub" \
  > "$tmp/summary.csv"
# The rows of the scenes not remade now, kept as they are.
if [ -f "$here/summary.csv" ]; then
  printf '%s\n' "${names[@]}" > "$tmp/names"
  awk -F, 'NR == FNR { skip[$1] = 1; next } FNR > 1 && !($1 in skip)' "$tmp/names" \
    "$here/summary.csv" >> "$tmp/summary.csv"
fi
for name in "${names[@]}"; do
  scene=$here/$name.json
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
# Rows by run name, then l (header first).
{ head -1 "$tmp/summary.csv"; tail -n +2 "$tmp/summary.csv" | sort -t, -k1,1 -k5,5g; } \
  > "$tmp/sorted.csv"
mv "$tmp/sorted.csv" "$here/summary.csv"
# The control against Fig. 5b's committed run of the same scene: the series up to l = 36.
control=$here/runs/mu_s-0.75_s1_control.h5
fig5b=$(ls "$here"/../fig5b/sweep/runs/mu_s-0.75_s1_*.h5 2> /dev/null | head -1)
if [ -f "$control" ] && [ -n "$fig5b" ]; then
  "$wp" export "$control" --csv "$tmp/a.csv"
  "$wp" export "$fig5b" --csv "$tmp/b.csv"
  n=$(wc -l < "$tmp/a.csv")
  # Every column but wall_s (17), the run's wall time.
  if cmp -s <(head -n "$n" "$tmp/b.csv" | cut -d, -f1-16,18-) <(cut -d, -f1-16,18- "$tmp/a.csv"); then
    echo "control: its series equals Fig. 5b's run $(basename "$fig5b") bitwise ($((n - 1)) rows)"
  else
    echo "control: its series DIFFERS from Fig. 5b's run $(basename "$fig5b")"
  fi
fi
column -s, -t "$here/summary.csv"
