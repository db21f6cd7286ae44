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
0 0.17461778747475815 0.0036427087466234798
0.1 0.18184676021662127 1.2196952849929943e-06
0.2 0.28354404876588124 7.658558519807457e-06
0.3 0.6132355822202809 0.005841643275837637
0.5 0.6443262504628363 6.416904412609448e-06
1 0.10518693328779544 3.4800266804357882e-06
EOD
reset
set grid
set key top left
set title "D = max of D(l) over l in [5, 20]: mean and SEM over seeds"
set xlabel "mu_s"
set ylabel "D"
set yrange [0:*]
set offsets graph 0.03, graph 0.03, graph 0.05, 0
plot $d0_0 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 notitle
set output
