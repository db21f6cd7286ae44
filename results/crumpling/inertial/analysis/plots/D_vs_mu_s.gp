# D_chord against mu_s (paper Fig. 5); data: ../D_vs_mu_s.csv
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
0.5 0.917507711832127 0.025731329116155034
1 0.9565598739796876 0.03956055329187434
EOD
$d0_1 << EOD
0.5 0.9181511048842715 0.024186031194832078
1 0.9560594924145233 0.04286088095429146
EOD
reset
set grid
set key top left
set title "D_chord = max of D_chord(l) over l in [5, 50]: mean and SEM over seeds"
set xlabel "mu_s"
set ylabel "D_chord"
set yrange [0:*]
set offsets graph 0.03, graph 0.03, graph 0.05, 0
plot $d0_0 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "D_chord", \
     $d0_1 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "literal D"
set output
