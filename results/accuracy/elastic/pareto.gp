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
17.899040248 0.019887755297795188 0
16.493210003 0.05000121539191856 0
EOD
$d0_1 << EOD
17.899040248 0.05688352161236124 0
9.712544109 0.9574457477174849 0
EOD
$d0_2 << EOD
17.899040248 0.05011151068964308 0
3.814351658 0.10707989631163857 0
EOD
$d0_3 << EOD
30.118168907 0.0376528500600211 0
17.899040248 0.013115801056728436 0
EOD
$d0_4 << EOD
3.814351658 0.02108691844780516 0
30.118168907 0.02108691844780516 0
EOD
$d1_0 << EOD
32.266677693 0.06261910321894402 0
31.601035481 0.13674454997141808 0
EOD
$d1_1 << EOD
32.266677693 0.48590955244289424 0
10.039605307 1.2801814311467303 0
EOD
$d1_2 << EOD
32.266677693 0.05300728681591945 0
4.988684779 0.33303483282513824 0
EOD
$d1_3 << EOD
52.429315279 0.24063480098565856 0
32.266677693 0.11556987750748719 0
EOD
$d1_4 << EOD
4.988684779 0.11097617840580294 0
52.429315279 0.11097617840580294 0
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
