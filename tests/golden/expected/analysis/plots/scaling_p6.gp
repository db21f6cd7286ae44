# Scaling with l of grid point 6 (log-log, fitted power laws); data: ../series.csv, ../exponents.csv
# Render: gnuplot scaling_p6.gp
if (!exists("out")) out = "scaling_p6.png"
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
0.5 7.679007396655341e-05 0
0.6 1.1842489980614296e-05 0
0.7 4.131013925067688e-06 0
0.8 4.197443270588278e-06 0
0.9 1.566527702880224e-06 0
1 1.1899063375145071e-06 0
1.1 7.922192833200417e-07 0
1.2 3.9000710421824176e-07 0
1.3 9.938114933775274e-07 0
1.4 9.175463347806213e-07 0
1.5 6.119844778510524e-07 0
1.6 6.062832212338346e-07 0
1.7 2.0951452802246222e-07 0
1.8 7.223041988758451e-07 0
1.9 3.325752546378386e-07 0
2 0.002371478776895458 0
2.1 0.007928646652531797 0
2.2 0.011602872184737236 0
2.3 0.015271687814607212 0
2.4 0.0178545978227324 0
2.5 0.020298051986918468 0
2.6 0.021170465453709555 0
2.7 0.0219121359811096 0
2.8 0.02311740964052396 0
2.9 0.023923451024009668 0
3 0.0249017494215424 0
3.1 0.025649137053342062 0
3.2 0.02586285105903202 0
3.3 0.027074094371280666 0
3.4 0.02807011236552047 0
3.5 0.028726177702928984 0
3.6 0.029815758437791384 0
3.7 0.030466517594982742 0
3.8 0.03122357165522826 0
3.9 0.03225925185860324 0
4 0.033271502164124736 0
EOD
$d3_1 << EOD
1.0003317394158449 6.218788692098497e-08 0
3.9001593985033276 0.23564841019691887 0
EOD
$d4_0 << EOD
0.5 0.060139861148612195 0
0.6 0.02952638137008074 0
0.7 0.018047724442997147 0
0.8 0.01331684207129349 0
0.9 0.011357945029868675 0
1 0.01060282539714789 0
1.1 0.007187754390358591 0
1.2 0.00668605287039691 0
1.3 0.007744920605132412 0
1.4 0.007999210556550871 0
1.5 0.005916215794160347 0
1.6 0.006126010705004292 0
1.7 0.004194487121237131 0
1.8 0.004931284345176191 0
1.9 0.004931239204372051 0
2 0.7832685080273394 0
2.1 1.5585525115257133 0
2.2 1.9088670845969602 0
2.3 2.245089670391816 0
2.4 2.3868022124818804 0
2.5 2.5827431368905396 0
2.6 2.7722982463208927 0
2.7 2.852081387555437 0
2.8 2.9709906067008505 0
2.9 3.124403891881328 0
3 3.2716245677000564 0
3.1 3.41160792196065 0
3.2 3.45846748435695 0
3.3 3.60964359531957 0
3.4 3.8308140392558085 0
3.5 3.8467370857770757 0
3.6 3.9755462223982763 0
3.7 4.129342264853733 0
3.8 4.238444601159279 0
3.9 4.445223757670817 0
4 4.6121585547100565 0
EOD
$d4_1 << EOD
1.0003317394158449 0.0017187380374676872 0
3.9001593985033276 12.402168612039093 0
EOD
$d5_0 << EOD
EOD
set multiplot layout 2,3 title "point 6: mu_s = 0.5, numerics.tolerance = 3e-04"
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
set title "delta = 11.132 +/- 0.81 (OLS)"
set xlabel "l"
set ylabel "U_b_hat"
set logscale x
set logscale y
plot $d3_0 using 1:2 with points pointtype 7 pointsize 0.5 title "seed mean", \
     $d3_1 using 1:2 with lines linewidth 2 title "fit on [1, 3.9]"
reset
set grid
set key bottom right
set title "lambda = 6.529 +/- 0.46 (OLS)"
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
