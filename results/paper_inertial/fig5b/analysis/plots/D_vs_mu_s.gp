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
0.5 0.9037279360422307 0.02099863121789942
1 0.9569209158400189 0.016359868388985968
EOD
$d0_1 << EOD
0.5 0.920862082111797 0.01884124066693051
1 0.9613261140708665 0.016198666591776656
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
