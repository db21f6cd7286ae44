# wirepack accuracy: error against wall time (Pareto front)
# Render: gnuplot pareto.gp
if (!exists("out")) out = "pareto.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 1000,400
} else {
  set terminal png noenhanced size 1000,400
}
set output out
set grid
set key top left
$d0_0 << EOD
180.638553711 0.00708757751082773 0
179.438468895 0.0043444399205040144 0
EOD
$d0_1 << EOD
179.438468895 0.008508038565900987 0
180.638553711 0.008508038565900987 0
EOD
$d1_0 << EOD
511.709693743 0.09206701516586259 0
423.19360334 0.017499973969360608 0
EOD
$d1_1 << EOD
423.19360334 0.0823278836513049 0
511.709693743 0.0823278836513049 0
EOD
set multiplot layout 1,2 title "accuracy vs time"
reset
set grid
set key top right
set title "mu_d=0 mu_s=0"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d0_0 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance", \
     $d0_1 using 1:2 with lines linewidth 2 title "seed floor"
reset
set grid
set key top right
set title "mu_d=0.45 mu_s=0.5"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d1_0 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance", \
     $d1_1 using 1:2 with lines linewidth 2 title "seed floor"
unset multiplot
set output
