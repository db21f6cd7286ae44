# D_chord against eps (paper Fig. 5); data: ../D_vs_eps.csv
# Render: gnuplot D_vs_eps.gp
if (!exists("out")) out = "D_vs_eps.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 800,600
} else {
  set terminal png noenhanced size 800,600
}
set output out
set grid
set key top left
$d0_0 << EOD
1 0.0034070987176064715 0.0034070987176064715
3 0 0
10 0 0
30 0 0
100 0.6816461648945259 0.3176734289307641
300 0.8149775314184704 0.18359274013440718
1000 0.8757307926833104 0.12410340404112452
3000 0.9098881831104386 0.08872850347286931
10000 0.9976733536758456 0
EOD
$d0_1 << EOD
1 0.6407876407111249 0.1455038760764785
3 0.21893357688949394 0.028563648282920517
10 0.41159130865455373 0.05779444543398481
30 0.15061297460775352 0.001032804611669935
100 0.7055194584753964 0.29321377017740363
300 0.8108150528953006 0.18780967395471632
1000 0.8800941219303264 0.11866475213752453
3000 0.9313513229747903 0.06731172180634282
10000 0.9989379676761241 0
EOD
reset
set grid
set key top left
set title "D_chord = max of D_chord(l) over l in [5, 50]: mean and SEM over seeds"
set xlabel "eps"
set ylabel "D_chord"
set logscale x
set yrange [0:*]
set offsets graph 0.03, graph 0.03, graph 0.05, 0
plot $d0_0 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "D_chord", \
     $d0_1 using 1:2:3 with yerrorlines pointtype 7 pointsize 0.8 title "literal D"
set output
