# D against numerics.tolerance (paper Fig. 5); data: ../D_vs_numerics.tolerance.csv
# Render: gnuplot D_vs_numerics.tolerance.gp
if (!exists("out")) out = "D_vs_numerics.tolerance.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 800,600
} else {
  set terminal png noenhanced size 800,600
}
set output out
set grid
set key top left
$d0_0 << EOD
3e-04 0.9705859585945763 0.029409471768493844
0.001 0.9411764982776731 2.438896917755784e-08
EOD
$d0_1 << EOD
3e-04 0.9111093283138536 0.022224011197183143
0.001 0.941176442267512 1.6925506718390437e-08
EOD
$d0_2 << EOD
3e-04 0.9111093283136773 0.022224011197359447
0.001 0.941176442267512 1.6925506718390437e-08
EOD
$d0_3 << EOD
3e-04 0.9111093283136773 0.022224011197359447
0.001 0.941176442267512 1.6925506718390437e-08
EOD
reset
set grid
set key top left
set title "D = max of D(l) over l in [1, 4]: mean and SEM over seeds"
set xlabel "numerics.tolerance"
set ylabel "D"
set yrange [0:*]
set offsets graph 0.03, graph 0.03, graph 0.05, 0
plot $d0_0 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "mu_s = 0", \
     $d0_1 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "mu_s = 0.1", \
     $d0_2 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "mu_s = 0.25", \
     $d0_3 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "mu_s = 0.5"
set output
