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
100 0.5225400749843259 0.4762404632182672
300 0.8986304442620341 0.0999370933369833
1000 0.8716416098724753 0.12823588379905188
3000 0.9998297539152354 0
EOD
$d0_1 << EOD
1 0.6407876407111249 0.1455038760764785
3 0.21893357688949394 0.028563648282920517
10 0.41159130865455373 0.05779444543398481
30 0.15061297460775352 0.001032804611669935
100 0.5589870455416606 0.4398951022055067
300 0.8860608667839687 0.11256672185038878
1000 0.8751199738493746 0.12354563416222841
3000 0.9989942552290609 0
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
