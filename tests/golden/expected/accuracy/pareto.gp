# wirepack accuracy: error against wall time (Pareto front)
# Render: gnuplot pareto.gp
if (!exists("out")) out = "pareto.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 1500,800
} else {
  set terminal png noenhanced size 1500,800
}
set output out
set grid
set key top left
$d0_0 << EOD
0.157690168 0.018248332465893788 0
0.123902733 0.009928546210936695 0
EOD
$d0_1 << EOD
0.123902733 0.01841886597873835 0
0.157690168 0.01841886597873835 0
EOD
$d1_0 << EOD
0.377972365 0.011975109711808953 0
0.356056128 0.004854503040165848 0
EOD
$d1_1 << EOD
0.356056128 0.0013845559295982302 0
0.377972365 0.0013845559295982302 0
EOD
$d2_0 << EOD
0.417045572 0.014219358271971764 0
0.076905595 0.007509025130150694 0
EOD
$d2_1 << EOD
0.076905595 0.0019336290192509143 0
0.417045572 0.0019336290192509143 0
EOD
$d3_0 << EOD
0.482492724 0.01365399892624299 0
0.424536227 0.007848845328618407 0
EOD
$d3_1 << EOD
0.424536227 0.0018030550885234503 0
0.482492724 0.0018030550885234503 0
EOD
set multiplot layout 2,3 title "accuracy vs time"
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
set title "mu_d=0.09000000000000001 mu_s=0.1"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d1_0 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance", \
     $d1_1 using 1:2 with lines linewidth 2 title "seed floor"
reset
set grid
set key top right
set title "mu_d=0.225 mu_s=0.25"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d2_0 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance", \
     $d2_1 using 1:2 with lines linewidth 2 title "seed floor"
reset
set grid
set key top right
set title "mu_d=0.45 mu_s=0.5"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d3_0 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance", \
     $d3_1 using 1:2 with lines linewidth 2 title "seed floor"
unset multiplot
set output
