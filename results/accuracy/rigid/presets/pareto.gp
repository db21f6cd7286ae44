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
0.802268374 0.030862548421036987 0
0.219703145 0.022862577648182072 0
EOD
reset
set grid
set key top right
set title "accuracy vs time\nmu_s=0 shell=rigid"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d0_0 using 1:2 with points pointtype 7 pointsize 0.5 title "combined"
set output
