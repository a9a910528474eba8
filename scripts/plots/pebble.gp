# SPDX-License-Identifier: BSL-1.0
# The pebble thrown up at 50 m/s against quadratic drag (pebble, RK4 dt = 0.01 s, apex and ground events).
load "scripts/plots/common.gp"
set terminal pngcairo size 1000,700 font "DejaVu Sans,12"
set output out."/pebble.png"
set title "A pebble thrown up at 50 m/s, quadratic drag (terminal speed 30 m/s), RK4 dt = 0.01 s" font ",13"
set xlabel "t (s)"
set ylabel "height y (m)"
set y2label "velocity v (m/s)"
set ytics nomirror
set y2tics
set xrange [0:10.5]
set yrange [0:140]
set y2range [-52:52]
# The key in its own band under the x label (`key below` alone lets the label and the box overlap).
set bmargin 7
set key at screen 0.5, screen 0.015 center bottom horizontal maxrows 2 width 2
g = 9.8; v0 = 50.0
free(t) = (t <= 2*v0/g) ? v0*t - g*t*t/2 : NaN
freev(t) = (t <= 2*v0/g) ? v0 - g*t : NaN
set samples 500
plot data."/pebble.csv" using 1:2 with lines ls 1 title "height, with drag", \
     free(x) with lines ls 1 dt 2 lw 1.5 title "height, without drag (v0 t − g t²/2)", \
     data."/pebble.csv" using 1:3 axes x1y2 with lines ls 2 title "velocity, with drag", \
     freev(x) axes x1y2 with lines ls 2 dt 2 lw 1.5 title "velocity, without drag", \
     0 axes x1y2 with lines lc rgb "#999999" lw 1 notitle
