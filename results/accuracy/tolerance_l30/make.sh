#!/usr/bin/env bash
# Reproduces results/accuracy/tolerance_l30/: the step tolerance over whole elastic runs
# (docs/measurements.md "Tolerance over a whole run"). rho = 20, xi = 10, eps = 1e3, mu_s = 0 and
# 0.5, l = 30, seeds 1 and 2, tolerance 1e-3 (the default since 2026-11-29) against 1e-4 (the
# default before). Each 1e-4 run at mu_s = 0.5 takes ~45 min on one core; the eight ~2 h of CPU.
# Usage (from anywhere, after scripts/setup.sh): bash results/accuracy/tolerance_l30/make.sh [THREADS]
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=results/accuracy/tolerance_l30
sweep=sweeps/tolerance_l30
build/wirepack sweep scenes/tolerance_l30.sweep.json --out $sweep --threads "${1:-$(nproc)}" > /dev/null
build/wirepack accuracy $sweep --window 5,30 --out $out
mkdir -p $sweep/csv
for f in $sweep/runs/*.h5; do
  build/wirepack export "$f" --csv "$sweep/csv/$(basename "$f" .h5 | sed 's/_[0-9a-f]*$//').csv"
done
gnuplot <<GP
set datafile separator ","
set terminal pngcairo size 1200,480 font ",9"
set output "$out/tolerance_D_Ub.png"
set multiplot layout 1,2
set xlabel "l = L/R"; set ylabel "D"; set yrange [0:1.05]; set key top right
plot for [m in "0 0.5"] for [t in "1e-04 0.001"] for [k in "1 2"] \
     "$sweep/csv/mu_s-".m."_tolerance-".t."_s".k.".csv" \
     using "l":"D" with lines lw 1 title "mu_s = ".m.", tol. ".t.", seed ".k
set ylabel "U_b hat"; set autoscale y; set key top left
plot for [m in "0 0.5"] for [t in "1e-04 0.001"] for [k in "1 2"] \
     "$sweep/csv/mu_s-".m."_tolerance-".t."_s".k.".csv" \
     using "l":"U_b_hat" with lines lw 1 title "mu_s = ".m.", tol. ".t.", seed ".k
unset multiplot
GP
