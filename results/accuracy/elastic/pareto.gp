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
32.290199793 0.043951985920893985 0
28.971900526 0.04987549879259078 0
EOD
$d0_1 << EOD
32.290199793 0.08157672598954074 0
18.56009923 0.9101306819250478 0
EOD
$d0_2 << EOD
32.290199793 0.02454978753645936 0
7.625075602 0.10500768838445222 0
EOD
$d0_3 << EOD
32.290199793 0.0376528500600211 0
19.096353151 0.013115801056728436 0
EOD
$d0_4 << EOD
7.625075602 0.04870164382357773 0
32.290199793 0.04870164382357773 0
EOD
$d1_0 << EOD
59.35828248 0.28134173682305513 0
68.815916008 0.18204577713460043 0
EOD
$d1_1 << EOD
59.35828248 0.2088965944603312 0
17.646586852 1.0733410847592113 0
EOD
$d1_2 << EOD
59.35828248 0.2971171637861471 0
10.599301262 0.28937019289951277 0
EOD
$d1_3 << EOD
59.35828248 0.24063480098565856 0
33.406977488 0.11556987750748719 0
EOD
$d1_4 << EOD
10.599301262 0.3081233542450529 0
68.815916008 0.3081233542450529 0
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
plot $d0_0 using 1:2 with points pointtype 7 pointsize 0.5 title "element_length", \
     $d0_1 using 1:2 with points pointtype 7 pointsize 0.5 title "quasistatic_ratio", \
     $d0_2 using 1:2 with points pointtype 7 pointsize 0.5 title "shell_mesh_size", \
     $d0_3 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance", \
     $d0_4 using 1:2 with lines linewidth 2 title "seed floor"
reset
set grid
set key top right
set title "mu_d=0.45 mu_s=0.5"
set xlabel "wall time per run [s]"
set ylabel "rel. RMS error of U_b hat, K (larger)"
set logscale x
set logscale y
plot $d1_0 using 1:2 with points pointtype 7 pointsize 0.5 title "element_length", \
     $d1_1 using 1:2 with points pointtype 7 pointsize 0.5 title "quasistatic_ratio", \
     $d1_2 using 1:2 with points pointtype 7 pointsize 0.5 title "shell_mesh_size", \
     $d1_3 using 1:2 with points pointtype 7 pointsize 0.5 title "tolerance", \
     $d1_4 using 1:2 with lines linewidth 2 title "seed floor"
unset multiplot
set output
