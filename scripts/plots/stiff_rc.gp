# SPDX-License-Identifier: BSL-1.0
# Stiffness on the RC discharge (stiff, part a): RC = 2 ms, V(0) = 1 V, every method at h = 2.5 RC.
load "scripts/plots/common.gp"
set terminal pngcairo size 1000,600 font "DejaVu Sans,12"
set output out."/stiff_rc.png"
set title "V′ = −V/RC, RC = 2 ms, steps of h = 2.5 RC: |V| on a log scale\nper step V is multiplied by R(−2.5): Euler −1.5, RK4 0.648, backward Euler 0.286, trapezoid −0.111, Radau IIA 0.0845" font ",12"
set xlabel "t (ms)"
set ylabel "|V| (V)"
set logscale y
set format y "10^{%L}"
set yrange [1e-24:1e4]
set xrange [0:100]
set key bottom left
plot data."/stiff_rc.csv" using ($1*1000):(abs($3)) with linespoints ls 2 pt 7 title "Euler: grows (|R| > 1)", \
     "" using ($1*1000):(abs($4)) with linespoints ls 4 pt 5 title "RK4: stable, far too slow a decay", \
     "" using ($1*1000):(abs($5)) with linespoints ls 1 pt 9 title "backward Euler (L-stable)", \
     "" using ($1*1000):(abs($6)) with linespoints ls 5 pt 11 title "trapezoid (A-stable, rings)", \
     "" using ($1*1000):(abs($7)) with linespoints ls 3 pt 13 title "Radau IIA (L-stable, order 5)", \
     "" using ($1*1000):2 with lines lc rgb "#000000" dt 2 title "exact exp(−t/RC)"
