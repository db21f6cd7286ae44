# Scaling with l of grid point 1 (log-log, fitted power laws); data: ../series.csv, ../exponents.csv
# Render: gnuplot scaling_p1.gp
if (!exists("out")) out = "scaling_p1.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 1500,900
} else {
  set terminal png noenhanced size 1500,900
}
set output out
set grid
set key top left
$d0_0 << EOD
EOD
$d1_0 << EOD
EOD
$d2_0 << EOD
EOD
$d3_0 << EOD
0.5 8.797378071354125e-05 0
0.6 9.878965527793405e-06 0
0.7 3.4177604340525346e-06 0
0.8 2.377437624134638e-06 0
0.9 1.3416421103155652e-06 0
1 8.957194627307618e-07 0
1.1 6.426699969503981e-07 0
1.2 2.045397745478954e-07 0
1.3 7.865374442552468e-07 0
1.4 7.80036496295684e-07 0
1.5 6.536394260174171e-07 0
1.6 6.070151180288333e-07 0
1.7 2.418420903364049e-07 0
1.8 6.584500279793476e-07 0
1.9 3.2029238869886375e-07 0
2 0.004026503862683102 0
2.1 0.007345102192109522 0
2.2 0.010960056398982801 0
2.3 0.013194962504476992 0
2.4 0.016134733622355554 0
2.5 0.017605834066902748 0
2.6 0.01923371874084788 0
2.7 0.021139084547134097 0
2.8 0.02168646075384245 0
2.9 0.022872959960874774 0
3 0.02316729575764542 0
3.1 0.023555343861233688 0
3.2 0.024023439889490995 0
3.3 0.024428395658959316 0
3.4 0.02494338298675381 0
3.5 0.02547267821525846 0
3.6 0.026130130892384307 0
3.7 0.026651105678624137 0
3.8 0.027421901196046865 0
3.9 0.027987410052883868 0
4 0.02856981698272348 0
EOD
$d3_1 << EOD
1.0000360913252686 5.116875860756539e-08 0
3.900147506207362 0.22483980035884474 0
EOD
$d4_0 << EOD
0.5 0.06269220718089531 0
0.6 0.022956503477891972 0
0.7 0.016652196825044284 0
0.8 0.00970942979647551 0
0.9 0.009394369494945242 0
1 0.0098946602569463 0
1.1 0.008019862962142726 0
1.2 0.003878399320825466 0
1.3 0.0052534355550851244 0
1.4 0.006035566831424401 0
1.5 0.005207852632947781 0
1.6 0.005023366618115132 0
1.7 0.004673887379080701 0
1.8 0.004225501569095428 0
1.9 0.004178182102258278 0
2 1.0536678782547089 0
2.1 1.451060420107577 0
2.2 1.8143619142381993 0
2.3 2.1624352049398015 0
2.4 2.145123203588793 0
2.5 2.5150842762629315 0
2.6 2.600431694161813 0
2.7 2.921809619830495 0
2.8 2.9044281101676868 0
2.9 2.9554905455867875 0
3 3.015887145816877 0
3.1 3.2184168204664054 0
3.2 3.2799164220970853 0
3.3 3.4290482514089247 0
3.4 3.5791438657177723 0
3.5 3.6478954992044486 0
3.6 3.7035383780907276 0
3.7 3.820730194454722 0
3.8 4.005211975399552 0
3.9 4.040310520742487 0
4 4.18110360005851 0
EOD
$d4_1 << EOD
1.0000360913252686 0.0014350511145524065 0
3.900147506207362 12.114346947846823 0
EOD
$d5_0 << EOD
EOD
set multiplot layout 2,3 title "point 1: mu_s = 0, numerics.tolerance = 0.001"
reset
set grid
set key bottom right
set title "alpha: no fit"
set xlabel "l"
set ylabel "R_t"
set label 1 "no data" at graph 0.5, 0.5 center
plot [0:1][0:1] NaN notitle
unset label 1
reset
set grid
set key bottom right
set title "beta: no fit"
set xlabel "l"
set ylabel "R_x"
set label 1 "no data" at graph 0.5, 0.5 center
plot [0:1][0:1] NaN notitle
unset label 1
reset
set grid
set key bottom right
set title "gamma: no fit"
set xlabel "l"
set ylabel "R_y"
set label 1 "no data" at graph 0.5, 0.5 center
plot [0:1][0:1] NaN notitle
unset label 1
reset
set grid
set key bottom right
set title "delta = 11.239 +/- 0.82 (OLS)"
set xlabel "l"
set ylabel "U_b_hat"
set logscale x
set logscale y
plot $d3_0 using 1:2 with points pointtype 7 pointsize 0.5 title "seed mean", \
     $d3_1 using 1:2 with lines linewidth 2 title "fit on [1, 3.9]"
reset
set grid
set key bottom right
set title "lambda = 6.643 +/- 0.48 (OLS)"
set xlabel "l"
set ylabel "K"
set logscale x
set logscale y
plot $d4_0 using 1:2 with points pointtype 7 pointsize 0.5 title "seed mean", \
     $d4_1 using 1:2 with lines linewidth 2 title "fit on [1, 3.9]"
reset
set grid
set key bottom right
set title "tau: no fit"
set xlabel "l"
set ylabel "N"
set label 1 "no data" at graph 0.5, 0.5 center
plot [0:1][0:1] NaN notitle
unset label 1
unset multiplot
set output
