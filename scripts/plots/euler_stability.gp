# SPDX-License-Identifier: BSL-1.0
# Euler's stability on the capacitor discharge (euler_accuracy, problem 3.17): RC = 2 ms, Q(0) = 10.
load "scripts/plots/common.gp"
set terminal pngcairo size 1000,600 font "DejaVu Sans,12"
set output out."/euler_stability.png"
set title "Euler on R dQ/dt = −Q/C, R = 2000 Ω, C = 1 µF (RC = 2 ms), Q(0) = 10 C: |Q| on a log scale\n(each step multiplies Q by 1 − dt/RC: −1.5 at dt = 2.5 RC)" font ",13"
set xlabel "t (ms)"
set ylabel "|Q| (C)"
set logscale y
set format y "10^{%L}"
set yrange [1e-16:1e4]
set xrange [0:50]
set key bottom left
plot data."/euler_stability.csv" index 0 using ($1*1000):(abs($2)) with linespoints ls 2 pt 7 title "dt = 5 ms (2.5 RC): unstable", \
     "" index 1 using ($1*1000):(abs($2)) with linespoints ls 4 pt 5 title "dt = 2.5 ms (1.25 RC): factor −0.25", \
     "" index 2 using ($1*1000):(abs($2)) with linespoints ls 1 pt 9 ps 0.6 title "dt = 1 ms (0.5 RC): factor 0.5", \
     "" index 3 using ($1*1000):2 with lines lc rgb "#000000" dt 2 title "exact 10 C exp(−t/RC)"
