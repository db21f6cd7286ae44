#!/usr/bin/env bash
# Where the reversed-curvature wire sits (results/paper/README.md, "The order parameter"): the
# signed curvature about the coil normal against arc length from the hole, from the snapshots
# (every 2 l) of the two runs of results/elastic (rho = 20, xi = 10, eps = 1e3, mu_s = 0 and 0.5,
# default numerics, l = 30; made by bash results/elastic/make.sh into runs/). Writes
# profiles/mu<m>_l<l>.csv (wirepack export --profile), variants.csv (D, D_chord, D_kappa and the
# entry chord's length per snapshot) and profile.png. Usage: bash results/paper/order_parameter/make.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
here=$root/results/paper/order_parameter
wp=$root/build/wirepack
mkdir -p "$here/profiles"
echo "mu_s,l,D,D_chord,D_kappa,chord_R" > "$here/variants.csv.part"
for mu in 0 0.5; do
  run=$root/runs/elastic_mu$mu.h5
  [ -f "$run" ] || { echo "make.sh: $run missing: run bash results/elastic/make.sh first" >&2; exit 2; }
  for k in $(seq 1 15); do
    csv=$here/profiles/mu${mu}_s$k.csv
    "$wp" export "$run" --profile "$csv" --snapshot "$k"
    # "# ..., l = L" and "# D = a, D_chord = b, D_kappa = c, entry chord = d R"
    awk -v mu="$mu" 'NR == 1 { sub(/.*l = /, ""); l = $0 }
      NR == 2 { gsub(/[#A-Za-z_=R ]/, ""); print mu "," l "," $0 }' "$csv" >> "$here/variants.csv.part"
  done
done
mv "$here/variants.csv.part" "$here/variants.csv"
gnuplot <<GP
set datafile separator ","
set terminal pngcairo size 1200,440 font ",9"
set output "$here/profile.png"
set multiplot layout 1,2
set xlabel "arc length from the hole s / R"; set ylabel "kappa_n R (about the coil normal)"
set xrange [0:3]; set key bottom left; set grid
set title "mu_s = 0: the entry chord turns against the coil"
plot for [k in "1 3 7 14"] "$here/profiles/mu0_s".k.".csv" using "s_R":"kappa_n_R" \
     with lines lw 1.5 title "l = ".(2*k)
set title "mu_s = 0.5"
plot for [k in "1 3 7 14"] "$here/profiles/mu0.5_s".k.".csv" using "s_R":"kappa_n_R" \
     with lines lw 1.5 title "l = ".(2*k)
unset multiplot
GP
column -s, -t "$here/variants.csv"
