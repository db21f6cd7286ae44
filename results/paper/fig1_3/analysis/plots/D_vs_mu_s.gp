# D against mu_s (paper Fig. 5); data: ../D_vs_mu_s.csv
# Render: gnuplot D_vs_mu_s.gp
if (!exists("out")) out = "D_vs_mu_s.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 800,600
} else {
  set terminal png noenhanced size 800,600
}
set output out
set grid
set key top left
$d0_0 << EOD
0 0.08164542714744638 0
0.5 0.7925059131010336 0
EOD
reset
set grid
set key top left
set title "D = max of D(l) over l in [5, 60]: mean and SEM over seeds"
set xlabel "mu_s"
set ylabel "D"
set yrange [0:*]
set offsets graph 0.03, graph 0.03, graph 0.05, 0
plot $d0_0 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 notitle
set output
