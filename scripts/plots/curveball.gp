# SPDX-License-Identifier: BSL-1.0
# Curveballs (curveball): side view and top view of each pitch to the plate at x = 18 m.
load "scripts/plots/common.gp"
set terminal pngcairo size 1100,900 font "DejaVu Sans,12"
set output out."/curveball.png"
set multiplot layout 2,1 title "Pitches from 1.8 m towards the plate 18 m away (C_D = 6·10^{-3}/m, C_M = 4·10^{-4}, spin 200 rad/s)" font ",13"
set xrange [0:18.5]
set xlabel "distance towards the plate x (m)"
set arrow 1 from 18,graph 0 to 18,graph 1 nohead lc rgb "#888888" dt 3
set title "side view"
set ylabel "height z (m)"
set yrange [1.0:2.5]
set key bottom left
plot data."/curveball.csv" index 0 using 2:4 with lines ls 8 title "40 m/s, no drag, aimed at 1.5 m", \
     "" index 1 using 2:4 with lines ls 1 title "40 m/s with drag, aimed at 1.5 m", \
     "" index 2 using 2:4 with lines ls 2 title "the same with topspin", \
     "" index 3 using 2:4 with lines ls 3 title "the same with backspin", \
     "" index 5 using 2:4 with lines ls 4 title "35 m/s curveball, spin about the vertical"
set title "top view"
set ylabel "sideways y (m)"
set yrange [-0.05:0.45]
set key top left
plot data."/curveball.csv" index 1 using 2:3 with lines ls 1 title "40 m/s pitches without sideways spin", \
     "" index 5 using 2:3 with lines ls 4 title "35 m/s curveball: 0.38 m to the side at the plate"
unset multiplot
