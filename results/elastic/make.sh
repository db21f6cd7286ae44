#!/usr/bin/env bash
# Reproduces results/elastic/: the two morphology scenes of the paper's Fig. 1/3 parameters
# (rho = 20, xi = 10, eps = 1e3) at mu_s = 0 and mu_s = 0.5, to l = 30, default numerics,
# seed 1; CSV series, D(l) plot and a picture of the last snapshot of each (`wirepack render`:
# ParaView, the wire at half radius coloured by kappa R, the shell by its area stretch; the
# gnuplot renderer where ParaView is not installed) and a movie of each (MP4, not committed).
# On the 2-core CI machine (both run in parallel): 4 min for mu_s = 0, 8 min for mu_s = 0.5
# (crumpling). Run from the repository root after scripts/setup.sh (--with-paraview for the
# ParaView pictures). Run files and movies go to runs/ (not committed). RENDER_ONLY=1 skips the
# runs and redraws from the run files in runs/.
set -euo pipefail
out=results/elastic
mkdir -p runs
if [ "${RENDER_ONLY:-0}" != 1 ]; then
  for mu in 0 0.5; do
    echo "{\"rho\": 20, \"xi\": 10, \"eps\": 1000, \"mu_s\": $mu, \"l_max\": 30,
          \"output\": {\"snapshots_every_l\": 2}}" > runs/elastic_mu$mu.json
    build/wirepack run runs/elastic_mu$mu.json --out runs/elastic_mu$mu.h5 2> runs/elastic_mu$mu.log &
  done
  wait
fi
for mu in 0 0.5; do
  build/wirepack export runs/elastic_mu$mu.h5 --csv $out/elastic_mu$mu.csv
  build/wirepack render runs/elastic_mu$mu.h5 --out $out/elastic_mu$mu.png --half-radius \
    --movie runs/elastic_mu$mu.mp4 --title "rho = 20, xi = 10, eps = 1e3, mu_s = $mu"
done
gnuplot <<'GP'
set datafile separator ","
set terminal pngcairo size 1000,420 font ",10"
set output "results/elastic/elastic_D_Ub.png"
set multiplot layout 1,2
set xlabel "l = L/R"; set ylabel "D"; set yrange [0:1.05]; set key top right
plot "results/elastic/elastic_mu0.csv" using "l":"D" with lines lw 1.5 title "mu_s = 0", \
     "results/elastic/elastic_mu0.5.csv" using "l":"D" with lines lw 1.5 title "mu_s = 0.5"
set ylabel "U_b hat"; set autoscale y; set key top left
plot "results/elastic/elastic_mu0.csv" using "l":"U_b_hat" with lines lw 1.5 title "mu_s = 0", \
     "results/elastic/elastic_mu0.5.csv" using "l":"U_b_hat" with lines lw 1.5 title "mu_s = 0.5"
unset multiplot
GP
