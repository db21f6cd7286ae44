# The four-dimensional phase diagram: x_c of mu_s from ../phase_diagram_4d.csv
# Render: gnuplot phase4d_mu_s.gp
if (!exists("out")) out = "phase4d_mu_s.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 900,700
} else {
  set terminal png noenhanced size 900,700
}
set output out
set grid
set key top left
$d0_0 << EOD
30 0.19293226658715923 0.1302487105256394 0.20011059833585768
100 0.1835752538203006 0.09777072473662454 0.19973252746449677
EOD
$d0_1 << EOD
10 0.25996206677615746 0.25027401685937084 0.2889448301923312
EOD
$d0_2 << EOD
10 0.21149433904247464 0.2 0.3
EOD
$d0_3 << EOD
10 0.1041806081347898 0.09614116849949787 0.11788561104059762
EOD
reset
set grid
set key outside bottom center
set title "critical mu_s against xi"
set xlabel "xi"
set ylabel "mu_s_c (bars: 95 % bootstrap interval)"
set xtics (10, 30, 100)
set logscale x
set autoscale fix
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
plot $d0_0 using 1:2:3:4 with yerrorlines pointtype 7 pointsize 0.8 title "eps = 100, rho = 20 (results/phase_diagram/runs/coarse)", \
     $d0_1 using ($1*10**(-0.02)):2:3:4 with yerrorlines pointtype 7 pointsize 0.8 title "eps = 1000, rho = 20 (results/paper/fig5b/sweep)", \
     $d0_2 using 1:2:3:4 with yerrorlines pointtype 7 pointsize 0.8 title "eps = 1000, rho = 20 (results/phase_diagram/runs/coarse)", \
     $d0_3 using ($1*10**(0.02)):2:3:4 with yerrorlines pointtype 7 pointsize 0.8 title "eps = 1000, rho = 20 (results/phase_diagram/runs/neo_hookean)"
set output
