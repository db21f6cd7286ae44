# Phase diagram: D (mean over seeds, colour) over numerics.tolerance and mu_s, with the critical mu_s (line) and its 95 % bootstrap interval (band); data: ../curves.csv, ../phase_diagram.csv
# Render: gnuplot phase_mu_s.gp
if (!exists("out")) out = "phase_mu_s.png"
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo noenhanced size 900,700
} else {
  set terminal png noenhanced size 900,700
}
set output out
set title "D and the critical mu_s against numerics.tolerance"
set xlabel "numerics.tolerance"
set ylabel "mu_s"
set cblabel "D (mean over seeds)"
set palette rgbformulae 33,13,10
set key outside top center horizontal
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
$D << EOD
3e-04 0 0.9705859585945763
0.001 0 0.9411764982776731
3e-04 0.1 0.9111093283138536
0.001 0.1 0.941176442267512
3e-04 0.25 0.9111093283136773
0.001 0.25 0.941176442267512
3e-04 0.5 0.9111093283136773
0.001 0.5 0.941176442267512
EOD
plot $D using 1:2:3 with points pointtype 5 pointsize 3 palette title "D"
