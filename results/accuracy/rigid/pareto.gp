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
0.809984188 0.008673106612072486 0
0.222207001 0.013233136157174294 0
EOD
$d0_1 << EOD
2.196581993 0.006692934718222609 0
0.809984188 0.03630622960784043 0
0.41795604 0.13841029945224684 0
0.21053924 0.6539984048320332 0
EOD
$d0_2 << EOD
2.153537771 0.015816941867830784 0
1.588108032 0.014988379699733738 0
1.106712634 0.005217037445401444 0
0.809984188 0.014311993423990402 0
EOD
$d0_3 << EOD
0.21053924 0.012132214247132877 0
2.196581993 0.012132214247132877 0
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
