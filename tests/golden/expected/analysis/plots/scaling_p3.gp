# Scaling with l of grid point 3 (log-log, fitted power laws); data: ../series.csv, ../exponents.csv
# Render: gnuplot scaling_p3.gp
if (!exists("out")) out = "scaling_p3.png"
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
2 0.0028531840098474713 0
2.1 0.007355061888020363 0
2.2 0.010875581835356227 0
2.3 0.013740388321759806 0
2.4 0.01624110260972468 0
2.5 0.01769457259892808 0
2.6 0.019094268485880795 0
2.7 0.020626451728333675 0
2.8 0.021716148464969564 0
2.9 0.022618408488629747 0
3 0.022960579184760264 0
3.1 0.023418035699187812 0
3.2 0.024049584933500318 0
3.3 0.02446812815285237 0
3.4 0.024937230463637355 0
3.5 0.025561084482716954 0
3.6 0.025984822083903358 0
3.7 0.02666766261332308 0
3.8 0.027043683274168832 0
3.9 0.02765965705047703 0
4 0.028362755034508275 0
EOD
$d3_1 << EOD
1.000389523405862 5.310637093184324e-08 0
3.900287174771412 0.21978311629512087 0
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
2 0.8661864357937723 0
2.1 1.4776500094186926 0
2.2 1.8491168498173407 0
2.3 2.2093848961403904 0
2.4 2.1667472907738166 0
2.5 2.5207276198733597 0
2.6 2.6474850606443656 0
2.7 2.8066119783500696 0
2.8 2.955543424666211 0
2.9 2.992619675062733 0
3 3.0420991427598096 0
3.1 3.1536137423723716 0
3.2 3.327729964751473 0
3.3 3.4623151846481885 0
3.4 3.5842761625279818 0
3.5 3.6346849725047 0
3.6 3.6941466148056206 0
3.7 3.819584722629492 0
3.8 3.96495617417705 0
3.9 3.994888923533873 0
4 4.165747049201311 0
EOD
$d4_1 << EOD
1.000389523405862 0.0015014684244317477 0
3.900287174771412 11.992295110131343 0
EOD
$d5_0 << EOD
EOD
set multiplot layout 2,3 title "point 3: mu_s = 0.1, numerics.tolerance = 0.001"
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
set title "delta = 11.197 +/- 0.82 (OLS)"
set xlabel "l"
set ylabel "U_b_hat"
set logscale x
set logscale y
plot $d3_0 using 1:2 with points pointtype 7 pointsize 0.5 title "seed mean", \
     $d3_1 using 1:2 with lines linewidth 2 title "fit on [1, 3.9]"
reset
set grid
set key bottom right
set title "lambda = 6.604 +/- 0.47 (OLS)"
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
