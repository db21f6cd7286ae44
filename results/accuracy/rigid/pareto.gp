# wirepack accuracy: error against wall time (Pareto front)
# Render: gnuplot pareto.gp
if (!exists("out")) out = "pareto.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 500,400
} else {
  set terminal png noenhanced size 500,400
}
set output out
set grid
set key top left
$d0_0 << EOD
2.217811264 0.010075905874405043 0
0.548486375 0.011155446092651247 0
EOD
$d0_1 << EOD
5.355395237 0.0063180724729345415 0
2.217811264 0.03674347886926587 0
0.841060402 0.14956872174836114 0
0.545303214 0.7996707998607654 0
EOD
$d0_2 << EOD
2.88957517 0.015816941867830784 0
2.217811264 0.014988379699733738 0
1.485438412 0.005217037445401444 0
1.094227152 0.014311993423990402 0
EOD
$d0_3 << EOD
0.545303214 0.014435679439543941 0
5.355395237 0.014435679439543941 0
EOD
reset
set grid
set key top right
set title "accuracy vs time\nmu_s=0 shell=rigid"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d0_0 using 1:2 with points pointtype 7 pointsize 0.5 title "element_length", \
     $d0_1 using 1:2 with points pointtype 7 pointsize 0.5 title "quasistatic_ratio", \
     $d0_2 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance", \
     $d0_3 using 1:2 with lines linewidth 2 title "seed floor"
set output
