# Scaling with l of grid point 0 (log-log, fitted power laws); data: ../series.csv, ../exponents.csv
# Render: gnuplot scaling_p0.gp
if (!exists("out")) out = "scaling_p0.png"
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
0.5 7.934413679158391e-05 0
0.6 1.2587460763664805e-05 0
0.7 3.4694933951286345e-06 0
0.8 3.696091552634019e-06 0
0.9 1.2922993177098994e-06 0
1 1.0374756534885287e-06 0
1.1 6.777608643979064e-07 0
1.2 3.9669916444571253e-07 0
1.3 9.776510649902174e-07 0
1.4 9.687428023251999e-07 0
1.5 6.296506314405192e-07 0
1.6 6.102882959615755e-07 0
1.7 1.8057135013838979e-07 0
1.8 7.130591546316538e-07 0
1.9 3.10957307120199e-07 0
2 0.002817665413315947 0
2.1 0.007729876123723566 0
2.2 0.011014863208553133 0
2.3 0.01321637413103513 0
2.4 0.01607481057819095 0
2.5 0.017628816465951623 0
2.6 0.019275313718658513 0
2.7 0.021122732146546492 0
2.8 0.021560623379866167 0
2.9 0.02285343313625704 0
3 0.02316964913071566 0
3.1 0.02358094584774253 0
3.2 0.024033384911160426 0
3.3 0.024480753141906734 0
3.4 0.02494994830857855 0
3.5 0.025445567085133534 0
3.6 0.026068694033460592 0
3.7 0.026667309227038655 0
3.8 0.02744869191769545 0
3.9 0.028042483852883292 0
4 0.02857927393929168 0
EOD
$d3_1 << EOD
1.000199214787598 6.041507444460064e-08 0
3.9000928490012674 0.21144642143148443 0
EOD
$d4_0 << EOD
0.5 0.061647980832499095 0
0.6 0.03056406073504492 0
0.7 0.0162899913354139 0
0.8 0.012589747648797427 0
0.9 0.010146630836340393 0
1 0.010080912894200638 0
1.1 0.006885573635536471 0
1.2 0.006799800245462976 0
1.3 0.008116380129197617 0
1.4 0.007263001089812922 0
1.5 0.005063405209484416 0
1.6 0.005726708235992185 0
1.7 0.0035359305252177934 0
1.8 0.004948943389582131 0
1.9 0.004531957301721476 0
2 0.8869372704786898 0
2.1 1.4744640637304869 0
2.2 1.7993319433943582 0
2.3 2.144529931266706 0
2.4 2.1739049336402596 0
2.5 2.508619512660211 0
2.6 2.5958442655586347 0
2.7 2.9307860990591603 0
2.8 2.9076155312954763 0
2.9 2.9823977527658982 0
3 3.0071163587793563 0
3.1 3.2071506795657423 0
3.2 3.287818300993391 0
3.3 3.4530837000645276 0
3.4 3.569794738729405 0
3.5 3.656732866699638 0
3.6 3.714448441474782 0
3.7 3.821001459220441 0
3.8 4.001314460964596 0
3.9 4.045424306016502 0
4 4.174203059685327 0
EOD
$d4_1 << EOD
1.000199214787598 0.001651167402282712 0
3.9000928490012674 11.679813142126193 0
EOD
$d5_0 << EOD
EOD
set multiplot layout 2,3 title "point 0: mu_s = 0, numerics.tolerance = 3e-04"
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
set title "delta = 11.073 +/- 0.82 (OLS)"
set xlabel "l"
set ylabel "U_b_hat"
set logscale x
set logscale y
plot $d3_0 using 1:2 with points pointtype 7 pointsize 0.5 title "seed mean", \
     $d3_1 using 1:2 with lines linewidth 2 title "fit on [1, 3.9]"
reset
set grid
set key bottom right
set title "lambda = 6.514 +/- 0.47 (OLS)"
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
