# SPDX-License-Identifier: BSL-1.0
# The convergence diagram (convergence): every method on the e = 0.5 Kepler orbit over 1.25 periods.
load "scripts/plots/common.gp"
set terminal pngcairo size 1800,1150 font "DejaVu Sans,12"
set output out."/convergence.png"
set multiplot layout 2,3 title "Every method on the Kepler orbit e = 0.5, 1.25 periods: position error against the step (top) and against the evaluations of the force (bottom)" font ",15"
set logscale xy
set format y "10^{%L}"
set format x "10^{%L}"
set yrange [1e-13:10]
set key top left font ",10" spacing 0.9 maxrows 7 width -1
set pointsize 0.6
files = "convergence_rk.csv convergence_newtonian.csv convergence_adams.csv"
array heads[3] = ["explicit Runge-Kutta tables", "Newtonian steppers (x and v apart)", "Adams methods (RK4 start)"]
array counts[3] = [14, 14, 5]
set xlabel "dt"
set xrange [1e-9:1]
set yrange [1e-13:1e5]
do for [f=1:3] {
    set title heads[f]
    plot for [i=0:counts[f]-1] data."/".word(files, f) index i using 2:4 with linespoints ls (i+1) pt (i%7+4) title columnheader(1)
}
unset key
set yrange [1e-13:10]
set xlabel "evaluations of the right-hand side (the same colours as above)"
set xrange [10:1e7]
set format x "10^{%L}"
do for [f=1:3] {
    set title heads[f]
    plot for [i=0:counts[f]-1] data."/".word(files, f) index i using 3:4 with linespoints ls (i+1) pt (i%7+4) title columnheader(1)
}
unset multiplot
