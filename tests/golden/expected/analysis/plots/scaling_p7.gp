# Scaling with l of grid point 7 (log-log, fitted power laws); data: ../series.csv, ../exponents.csv
# Render: gnuplot scaling_p7.gp
if (!exists("out")) out = "scaling_p7.png"
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
0.5 0.00010149504955459799 0
0.6 9.090735981223044e-06 0
0.7 3.721777282462402e-06 0
0.8 1.8968622746095416e-06 0
0.9 1.1018815841106287e-06 0
1 1.0145277249185403e-06 0
1.1 6.509268977471318e-07 0
1.2 2.4120326918434874e-07 0
1.3 8.622979966663425e-07 0
1.4 7.513474813526753e-07 0
1.5 6.834839338695248e-07 0
1.6 5.393629072675148e-07 0
1.7 2.3638150372921474e-07 0
1.8 6.863646265958921e-07 0
1.9 3.421441463510594e-07 0
2 0.0028810648608951347 0
2.1 0.007936361189079316 0
2.2 0.011864277915882723 0
2.3 0.014908308842783713 0
2.4 0.01775117272774583 0
2.5 0.01989056778855677 0
2.6 0.02133552825552837 0
2.7 0.022213680588138586 0
2.8 0.022995884991664675 0
2.9 0.0241302842546536 0
3 0.02472296299035695 0
3.1 0.025752734049209032 0
3.2 0.025850020591510158 0
3.3 0.027082535341676817 0
3.4 0.027975889577448846 0
3.5 0.028781442877928096 0
3.6 0.029687588344690187 0
3.7 0.030395513692280624 0
3.8 0.03129874341832295 0
3.9 0.032249759562701916 0
4 0.03330565709036898 0
EOD
$d3_1 << EOD
1.000389523405862 5.128358941748598e-08 0
3.900266182627772 0.24963392050503605 0
EOD
$d4_0 << EOD
0.5 0.06876929890858116 0
0.6 0.01930579071043502 0
0.7 0.01670696956813958 0
0.8 0.00823729990991012 0
0.9 0.008291639005835967 0
1 0.009816153542256737 0
1.1 0.007324276141531562 0
1.2 0.004904617654826958 0
1.3 0.00646951243590319 0
1.4 0.005787659515986758 0
1.5 0.00584127118047059 0
1.6 0.004263859439345626 0
1.7 0.004153570386265136 0
1.8 0.005092483253709127 0
1.9 0.004707594593903597 0
2 0.8684225825464538 0
2.1 1.5226644193560932 0
2.2 1.9385281297920465 0
2.3 2.251537520943457 0
2.4 2.369831346045302 0
2.5 2.552683033489488 0
2.6 2.7735347462737403 0
2.7 2.880637549366871 0
2.8 2.9739912186670496 0
2.9 3.1298304232715197 0
3 3.225474383715942 0
3.1 3.4137722846048844 0
3.2 3.4873354303699298 0
3.3 3.6373288874796437 0
3.4 3.827564525187494 0
3.5 3.87127808401247 0
3.6 3.9644878152186322 0
3.7 4.124868636077287 0
3.8 4.231729043219229 0
3.9 4.4165040878176285 0
4 4.609926332531856 0
EOD
$d4_1 << EOD
1.000389523405862 0.001468954486675351 0
3.900266182627772 12.851214981597487 0
EOD
$d5_0 << EOD
EOD
set multiplot layout 2,3 title "point 7: mu_s = 0.5, numerics.tolerance = 0.001"
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
set title "delta = 11.317 +/- 0.82 (OLS)"
set xlabel "l"
set ylabel "U_b_hat"
set logscale x
set logscale y
plot $d3_0 using 1:2 with points pointtype 7 pointsize 0.5 title "seed mean", \
     $d3_1 using 1:2 with lines linewidth 2 title "fit on [1, 3.9]"
reset
set grid
set key bottom right
set title "lambda = 6.671 +/- 0.47 (OLS)"
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
