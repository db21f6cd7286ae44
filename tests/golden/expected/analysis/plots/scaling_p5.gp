# Scaling with l of grid point 5 (log-log, fitted power laws); data: ../series.csv, ../exponents.csv
# Render: gnuplot scaling_p5.gp
if (!exists("out")) out = "scaling_p5.png"
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
2 0.002876379105685406 0
2.1 0.007946614428438605 0
2.2 0.011870615797845638 0
2.3 0.014713209484690914 0
2.4 0.017158171826610426 0
2.5 0.018746981931983896 0
2.6 0.01977269028537236 0
2.7 0.020988757929059337 0
2.8 0.02209797503901633 0
2.9 0.022620826407506858 0
3 0.022989563184355768 0
3.1 0.02355727595672967 0
3.2 0.024269300900755082 0
3.3 0.024688757968036056 0
3.4 0.025428428438586503 0
3.5 0.02585667918377761 0
3.6 0.026707326017282186 0
3.7 0.027267249854433573 0
3.8 0.02803268869200483 0
3.9 0.028340884215841626 0
4 0.029163509658906076 0
EOD
$d3_1 << EOD
1.000389523405862 5.3333207320379864e-08 0
3.900034575719194 0.22616166746181043 0
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
2 0.8681510693304477 0
2.1 1.526334109130428 0
2.2 1.937967613233178 0
2.3 2.2413073284919367 0
2.4 2.3068138597579058 0
2.5 2.50198295705967 0
2.6 2.735190446217195 0
2.7 2.781554024558142 0
2.8 2.967761030517716 0
2.9 3.088509253778332 0
3 3.112522630294551 0
3.1 3.246650968999178 0
3.2 3.3239444886630904 0
3.3 3.422815628547618 0
3.4 3.5928147884259163 0
3.5 3.5914442606901087 0
3.6 3.7920847538507663 0
3.7 3.8841527114614554 0
3.8 4.047246237524444 0
3.9 4.132468745470851 0
4 4.222337265993093 0
EOD
$d4_1 << EOD
1.000389523405862 0.001501027390396374 0
3.900034575719194 12.212424972092288 0
EOD
$d5_0 << EOD
EOD
set multiplot layout 2,3 title "point 5: mu_s = 0.25, numerics.tolerance = 0.001"
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
set title "delta = 11.216 +/- 0.82 (OLS)"
set xlabel "l"
set ylabel "U_b_hat"
set logscale x
set logscale y
plot $d3_0 using 1:2 with points pointtype 7 pointsize 0.5 title "seed mean", \
     $d3_1 using 1:2 with lines linewidth 2 title "fit on [1, 3.9]"
reset
set grid
set key bottom right
set title "lambda = 6.618 +/- 0.47 (OLS)"
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
