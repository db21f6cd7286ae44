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
0 0.178334092217241 0.003531168296728226
0.1 0.18003914530405762 0.001805573825809925
0.2 0.28657734323185846 0.0015260883878250862
0.3 0.6013641243816583 0.022932203116728996
0.5 0.6815071553689471 0.03718822208752104
1 0.10518581351280604 7.003641459557564e-07
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
