# Scaling with l of grid point 4 (log-log, fitted power laws); data: ../series.csv, ../exponents.csv
# Render: gnuplot scaling_p4.gp
if (!exists("out")) out = "scaling_p4.png"
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
2 0.002411846916415222 0
2.1 0.007954905721921679 0
2.2 0.011644852274916887 0
2.3 0.015074207017391705 0
2.4 0.017279166968954845 0
2.5 0.019195211056443076 0
2.6 0.01979786487341082 0
2.7 0.02115534059490589 0
2.8 0.02184456263086077 0
2.9 0.022581156567537314 0
3 0.023081410953427584 0
3.1 0.023404346443811248 0
3.2 0.024263071191342363 0
3.3 0.024741227692727512 0
3.4 0.025432512131496453 0
3.5 0.025878325145363135 0
3.6 0.026759375181649017 0
3.7 0.02738805776707466 0
3.8 0.028027587391399742 0
3.9 0.028324682180723308 0
4 0.029168685011529638 0
EOD
$d3_1 << EOD
1.0003317394158449 6.47715553851879e-08 0
3.9001525561544015 0.21399531608458294 0
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
2 0.7908264952534643 0
2.1 1.559412686589033 0
2.2 1.906840526873545 0
2.3 2.2295210947443067 0
2.4 2.3286681084818768 0
2.5 2.5456684088178685 0
2.6 2.7105114194739066 0
2.7 2.7929346893940368 0
2.8 2.950107628162159 0
2.9 3.0517821191762113 0
3 3.108551239565661 0
3.1 3.2410545032601625 0
3.2 3.317598284465604 0
3.3 3.4284585082003876 0
3.4 3.58848540842641 0
3.5 3.5921512358439776 0
3.6 3.7971890289937287 0
3.7 3.8717090757957044 0
3.8 4.045588285489096 0
3.9 4.132226571363765 0
4 4.2312995962818665 0
EOD
$d4_1 << EOD
1.0003317394158449 0.001758075291990651 0
3.9001525561544015 11.77883655643577 0
EOD
$d5_0 << EOD
EOD
set multiplot layout 2,3 title "point 4: mu_s = 0.25, numerics.tolerance = 3e-04"
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
set title "delta = 11.032 +/- 0.82 (OLS)"
set xlabel "l"
set ylabel "U_b_hat"
set logscale x
set logscale y
plot $d3_0 using 1:2 with points pointtype 7 pointsize 0.5 title "seed mean", \
     $d3_1 using 1:2 with lines linewidth 2 title "fit on [1, 3.9]"
reset
set grid
set key bottom right
set title "lambda = 6.475 +/- 0.47 (OLS)"
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
