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
1 0.006814197435212943 0
100 0.9993194414587594 0.0005389032561664009
300 0.9985702715528776 0
3000 0.8211596796375693 0
EOD
$d0_1 << EOD
1 0.4952837646346464 0
100 0.9987332160450177 0.00014893170214957951
300 0.9986247268500169 0
3000 0.8640396011684475 0
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
