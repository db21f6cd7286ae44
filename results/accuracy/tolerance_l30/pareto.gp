# wirepack accuracy: error against wall time (Pareto front)
# Render: gnuplot pareto.gp
if (!exists("out")) out = "pareto.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 1000,400
} else {
  set terminal png noenhanced size 1000,400
}
set output out
set grid
set key top left
$d0_0 << EOD
180.638553711 0.00708757751082773 0
EOD
$d1_0 << EOD
511.709693743 0.09206701516586259 0
EOD
set multiplot layout 1,2 title "accuracy vs time"
reset
set grid
set key top right
set title "mu_d=0 mu_s=0"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d0_0 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance"
reset
set grid
set key top right
set title "mu_d=0.45 mu_s=0.5"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d1_0 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance"
unset multiplot
set output
