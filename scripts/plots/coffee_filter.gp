# SPDX-License-Identifier: BSL-1.0
# The coffee filter (coffee_filter): the course's readings and the two drag laws fitted to them.
load "scripts/plots/common.gp"
set terminal pngcairo size 1400,600 font "DejaVu Sans,12"
set output out."/coffee_filter.png"
set multiplot layout 1,2 title "A falling coffee filter: the course's 27 readings and least-squares fits with g = 9.8 m/s²" font ",13"
set title "height"
set xlabel "t (s)"
set ylabel "y (m)"
set key top right
plot data."/coffee_filter.csv" using 1:2 with points pt 7 ps 1.0 lc rgb "#000000" title "readings", \
     data."/coffee_filter_models.csv" index 0 using 1:2 with lines ls 1 title "quadratic drag, all readings", \
     "" index 1 using 1:2 with lines ls 2 title "linear drag, all readings", \
     "" index 2 using 1:2 with lines ls 1 dt 2 title "quadratic, from 0.45 s", \
     "" index 3 using 1:2 with lines ls 2 dt 2 title "linear, from 0.45 s"
set title "acceleration against velocity (central differences)"
set xlabel "v (m/s)"
set ylabel "a (m/s²)"
set xrange [-0.8:0]
set yrange [-10.5:8]
set key bottom left
# the later fits' terminal speeds (rows 4 and 5 of coffee_filter_fits.csv: quadratic, linear)
vq = real(system("awk -F, 'NR == 4 { print $3 }' ".data."/coffee_filter_fits.csv"))
vl = real(system("awk -F, 'NR == 5 { print $3 }' ".data."/coffee_filter_fits.csv"))
plot data."/coffee_filter.csv" using 3:4 with points pt 7 ps 1.0 lc rgb "#000000" title "readings", \
     -9.8*(1 - x*x/vq**2) with lines ls 1 dt 2 title sprintf("quadratic, vt = %.3f m/s (later fit)", vq), \
     -9.8*(1 + x/vl) with lines ls 2 dt 2 title sprintf("linear, vt = %.3f m/s (later fit)", vl)
unset multiplot
