#!/usr/bin/env bash
# Reproduces results/quasistatic/: the measurements of the quasi-static numerics
# (docs/measurements.md "Quasi-static regime").
#  1. damping.csv: the phase against the damping ratio zeta in {0.02, 0.05, 0.2, 0.5} at
#     mu_s = 0.3 and 0.5 (rho = 20, xi = 10, eps = 1e3, seed 1, l = 12, default numerics): D
#     maximised and averaged over l in [5, 12] (scenes/damping_sensitivity.sweep.json).
#  2. kinetic.csv: E_kin / U_b of the elastic reference runs (results/elastic, to l = 30) over
#     windows of l, before (the uniform mass scaling, the series committed in 57ad176) and now.
# ~25 min of CPU for the sweep. Usage (after scripts/setup.sh and results/elastic/make.sh):
#   bash results/quasistatic/make.sh [THREADS]
set -euo pipefail
cd "$(dirname "$0")/../.."
out=results/quasistatic
build/wirepack sweep scenes/damping_sensitivity.sweep.json --out sweeps/damping_sensitivity \
  --threads "${1:-$(nproc)}" > /dev/null
build/wirepack analyze sweeps/damping_sensitivity --out sweeps/damping_sensitivity/analysis \
  --no-plots 2> /dev/null
# One row per (mu_s, zeta): columns of curves.csv by name.
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i;
                   print "mu_s,damping_ratio,D_max,D_avg,U_b_hat_final"; next }
         { print $c["mu_s"] "," $c["numerics.damping_ratio"] "," $c["D_mean"] "," \
                 $c["D_avg_mean"] "," $c["U_b_hat_mean"] }' \
  sweeps/damping_sensitivity/analysis/curves.csv > $out/damping.csv.tmp
mv $out/damping.csv.tmp $out/damping.csv
# E_kin / U_b: mean and max over l windows, before and now.
stats() {  # stats LABEL MU CSV-TEXT
  awk -F, -v label="$1" -v mu="$2" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { l = $c["l"]; r = $c["U_b"] > 0 ? $c["E_kin"] / $c["U_b"] : 0
      for (w = 0; w < 5; ++w) if (l >= 5 + 5 * w && l <= 10 + 5 * w) {
        s[w] += r; n[w]++; if (r > m[w]) m[w] = r } }
    END { for (w = 0; w < 5; ++w) if (n[w] > 0)
            printf "%s,%s,%d,%d,%.5f,%.5f\n", label, mu, 5 + 5 * w, 10 + 5 * w, s[w] / n[w], m[w] }'
}
{
  echo "numerics,mu_s,l_min,l_max,E_kin_over_U_b_mean,E_kin_over_U_b_max"
  for mu in 0 0.5; do
    git show 57ad176:results/elastic/elastic_mu$mu.csv | stats uniform_q0.01 $mu
    stats selective_q0.01 $mu < results/elastic/elastic_mu$mu.csv
  done
} > $out/kinetic.csv.tmp
mv $out/kinetic.csv.tmp $out/kinetic.csv
echo "$out: damping.csv, kinetic.csv"
