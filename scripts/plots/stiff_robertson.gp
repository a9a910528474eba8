# SPDX-License-Identifier: BSL-1.0
# Robertson's kinetics (stiff, part b): Radau IIA, 20 fixed steps per decade of t, to t = 40.
load "scripts/plots/common.gp"
set terminal pngcairo size 1000,600 font "DejaVu Sans,12"
set output out."/stiff_robertson.png"
set title "Robertson's kinetics with Radau IIA, 160 fixed steps to t = 40 (RK4 fails at dt = 0.01)" font ",13"
set xlabel "t"
set ylabel "concentration"
set logscale x
set format x "10^{%L}"
set xrange [1e-7:40]
set yrange [0:1.05]
set key center left
plot data."/stiff_robertson.csv" using 1:2 with linespoints ls 1 pt 7 ps 0.6 title "y1", \
     "" using 1:3 with linespoints ls 2 pt 7 ps 0.6 title "10^4 y2", \
     "" using 1:4 with linespoints ls 3 pt 7 ps 0.6 title "y3"
