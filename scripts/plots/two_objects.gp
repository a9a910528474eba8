# SPDX-License-Identifier: BSL-1.0
# Two objects from 10 m, one dropped and one thrown at 30 m/s (steel_ball, problem 3.8).
load "scripts/plots/common.gp"
set terminal pngcairo size 1000,600 font "DejaVu Sans,12"
set output out."/two_objects.png"
set title "From 10 m: dropped and thrown sideways at 30 m/s; height against time" font ",13"
set xlabel "t (s)"
set ylabel "height (m)"
set yrange [0:10.5]
set xrange [0:2]
set key bottom left samplen 4
plot data."/two_objects.csv" index 0 using 1:3 with lines ls 8 lw 4 title "no drag: both together", \
     "" index 2 using 1:3 with lines ls 1 title "quadratic drag, dropped", \
     "" index 3 using 1:3 with lines ls 1 dt 2 title "quadratic drag, thrown: lands later", \
     "" index 4 using 1:3 with lines ls 2 lw 4 title "linear drag, dropped", \
     "" index 5 using 1:3 with lines lc rgb "#000000" dt (10,6) lw 1.5 title "linear drag, thrown: together (black dashes)"
