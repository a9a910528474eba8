# SPDX-License-Identifier: BSL-1.0
# Kepler energy over 10^6 steps (kepler_energy): e = 0.5, 200 steps per period, 5000 periods.
load "scripts/plots/common.gp"
set terminal pngcairo size 1000,650 font "DejaVu Sans,12"
set output out."/kepler_energy.png"
set title "Kepler orbit e = 0.5, 200 steps per period, 10^6 steps:\nlargest relative energy error in each window of 1000 steps" font ",13"
set logscale xy
set format y "10^{%L}"
set xlabel "time (periods)"
set ylabel "|ΔE / E_0|"
set xrange [4:5100]
set yrange [1e-7:3e-2]
set key bottom right
plot data."/kepler_energy.csv" index 0 using 1:2 with lines ls 2 title columnheader(1), \
     "" index 1 using 1:2 with lines ls 1 title columnheader(1), \
     "" index 2 using 1:2 with lines ls 3 title columnheader(1), \
     "" index 3 using 1:2 with lines ls 5 title columnheader(1)
