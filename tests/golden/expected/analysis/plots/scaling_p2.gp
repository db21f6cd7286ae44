# Scaling with l of grid point 2 (log-log, fitted power laws); data: ../series.csv, ../exponents.csv
# Render: gnuplot scaling_p2.gp
if (!exists("out")) out = "scaling_p2.png"
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
1.9 3.325760230569427e-07 0
2 0.0024173268733826223 0
2.1 0.00760638755287979 0
2.2 0.010698039731844439 0
2.3 0.013760963556489592 0
2.4 0.016307446136627903 0
2.5 0.01764996213041573 0
2.6 0.019152212241491204 0
2.7 0.02052368714166091 0
2.8 0.02175629529600113 0
2.9 0.0226763761410552 0
3 0.022940007024989446 0
3.1 0.02329059326517987 0
3.2 0.024076146986525535 0
3.3 0.024442191450651317 0
3.4 0.02496824153090047 0
3.5 0.0255638776959457 0
3.6 0.025984046886592747 0
3.7 0.026728769123515572 0
3.8 0.027020420095609683 0
3.9 0.02774582369254238 0
4 0.02838468670544328 0
EOD
$d3_1 << EOD
1.0003317394158449 6.455734376041196e-08 0
3.9002660722428457 0.2076153800751002 0
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
1.9 0.004931253894201852 0
2 0.7919970797331539 0
2.1 1.518306287984157 0
2.2 1.8253020553126729 0
2.3 2.197412994811912 0
2.4 2.1963301760884857 0
2.5 2.5165390001029033 0
2.6 2.650591365775285 0
2.7 2.802356391207725 0
2.8 2.9592726853291076 0
2.9 2.995882239385523 0
3 3.059491712566064 0
3.1 3.1559394867459343 0
3.2 3.3412912221402715 0
3.3 3.4556367602466143 0
3.4 3.5742133459800964 0
3.5 3.6307104826569327 0
3.6 3.7096548195579064 0
3.7 3.840705839861977 0
3.8 3.9571155547667916 0
3.9 3.991138026557801 0
4 4.1729111012536375 0
EOD
$d4_1 << EOD
1.0003317394158449 0.0017582053318709655 0
3.9002660722428457 11.590030926619786 0
EOD
$d5_0 << EOD
EOD
set multiplot layout 2,3 title "point 2: mu_s = 0.1, numerics.tolerance = 3e-04"
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
set title "delta = 11.012 +/- 0.81 (OLS)"
set xlabel "l"
set ylabel "U_b_hat"
set logscale x
set logscale y
plot $d3_0 using 1:2 with points pointtype 7 pointsize 0.5 title "seed mean", \
     $d3_1 using 1:2 with lines linewidth 2 title "fit on [1, 3.9]"
reset
set grid
set key bottom right
set title "lambda = 6.462 +/- 0.46 (OLS)"
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
