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
0 0.9705859585945763 0.029409471768493844
0.1 0.9111093283138536 0.022224011197183143
0.25 0.9111093283136773 0.022224011197359447
0.5 0.9111093283136773 0.022224011197359447
EOD
$d0_1 << EOD
0 0.9411764982776731 2.438896917755784e-08
0.1 0.941176442267512 1.6925506718390437e-08
0.25 0.941176442267512 1.6925506718390437e-08
0.5 0.941176442267512 1.6925506718390437e-08
EOD
reset
set grid
set key top left
set title "D = max of D(l) over l in [1, 4]: mean and SEM over seeds"
set xlabel "mu_s"
set ylabel "D"
set yrange [0:*]
set offsets graph 0.03, graph 0.03, graph 0.05, 0
plot $d0_0 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "numerics.tolerance = 3e-04", \
     $d0_1 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "numerics.tolerance = 0.001"
set output
