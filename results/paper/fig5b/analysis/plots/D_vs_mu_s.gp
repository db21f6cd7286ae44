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
0.05 0.0620294281682674 0.00048112018607759927
0.1 0.06831595030751536 0.008608193315717272
0.15 0.07518367206166582 0.0005674851895177135
0.2 0.07517147727133067 0.0005746699789094256
0.25 0.21054951274829042 0.009094555581181385
0.3 0.5875761937944587 0.0036177492130918805
0.75 0.8687936675267691 0
1 0.02382996125814274 0
EOD
$d0_1 << EOD
0.05 0.16835541786975866 0.009903321967172194
0.1 0.16494846442014877 0.006502264986236516
0.15 0.17041681230639877 0.007832317708592329
0.2 0.17898425451403527 0.019051354228692696
0.25 0.20949479080979394 0.009048955102983201
0.3 0.5731504482795974 0.001831822099805369
0.75 0.8864944182299019 0
1 0.0709734688459055 0
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
