#!/usr/bin/env bash
# Reproduces results/rigid/: two rigid-sphere runs (rho = 20, l = 20; mu_s = 0 and 1), their
# series as CSV and a plot of D(l) and U_b_hat(l). Run from the repository root after
# scripts/setup.sh. Run files go to runs/ (not committed).
set -euo pipefail
out=results/rigid
mkdir -p runs
for mu in 0 1; do
  echo "{\"rho\": 20, \"mu_s\": $mu, \"shell\": \"rigid\", \"l_max\": 20}" > runs/rigid_mu$mu.json
  build/wirepack run runs/rigid_mu$mu.json --out runs/rigid_mu$mu.h5
  build/wirepack export runs/rigid_mu$mu.h5 --csv $out/rigid_mu$mu.csv
done
gnuplot <<'GP'
set datafile separator ","
set terminal pngcairo size 1000,420 font ",10"
set output "results/rigid/rigid_D_Ub.png"
set multiplot layout 1,2
set xlabel "l = L/R"; set ylabel "D"; set yrange [0:1.05]; set key top right
plot "results/rigid/rigid_mu0.csv" using "l":"D" with lines lw 1.5 title "mu_s = 0", \
     "results/rigid/rigid_mu1.csv" using "l":"D" with lines lw 1.5 title "mu_s = 1"
set ylabel "U_b hat"; set autoscale y; set key top left
plot "results/rigid/rigid_mu0.csv" using "l":"U_b_hat" with lines lw 1.5 title "mu_s = 0", \
     "results/rigid/rigid_mu1.csv" using "l":"U_b_hat" with lines lw 1.5 title "mu_s = 1"
unset multiplot
GP
