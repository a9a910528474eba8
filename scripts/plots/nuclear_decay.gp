# SPDX-License-Identifier: BSL-1.0
# Multiple nuclear decays (nuclear_decay): 76Kr -> 76Br -> 76Se, RK4 against Bateman's closed form.
load "scripts/plots/common.gp"
set terminal pngcairo size 1000,600 font "DejaVu Sans,12"
set output out."/nuclear_decay.png"
set title "^{76}Kr (14.8 h) → ^{76}Br (16.1 h) → ^{76}Se from 1 g of ^{76}Kr: RK4 (lines) and Bateman's formula (points)" font ",13"
set xlabel "t (hours)"
set ylabel "mass (g)"
set xrange [0:168]
set xtics 24
set yrange [0:1.02]
set key center right
plot data."/nuclear_decay.csv" using 1:2 with lines ls 1 title "Kr-76", \
     "" using 1:3 with lines ls 2 title "Br-76", \
     "" using 1:4 with lines ls 3 title "Se-76", \
     "" every 40 using 1:5 with points pt 6 ps 1.2 lc rgb "#1f77b4" title "Bateman", \
     "" every 40 using 1:6 with points pt 6 ps 1.2 lc rgb "#d62728" notitle, \
     "" every 40 using 1:7 with points pt 6 ps 1.2 lc rgb "#2ca02c" notitle
