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
# Up to 14 curves a panel, each in a colour of its own (14 of Kelly's 22 colours of maximum contrast), the
# second seven also dashed, and each with a point type of its own: no two curves of a panel look alike, in
# colour or in black and white.
array colours[14] = ["#0067a5", "#be0032", "#008856", "#f38400", "#875692", "#222222", "#a1caf1", \
                     "#882d17", "#8db600", "#e68fac", "#848482", "#b3446c", "#c2b280", "#2b8cbe"]
do for [i=1:14] {
    dash = i <= 7 ? 1 : 2
    set style line 20+i lc rgb colours[i] lw 2 dt dash pt i
}
files = "convergence_rk.csv convergence_newtonian.csv convergence_adams.csv"
array heads[3] = ["explicit Runge-Kutta tables", "Newtonian steppers (x and v apart)", "Adams methods (RK4 start)"]
array counts[3] = [14, 14, 5]
set xlabel "dt"
set ylabel "position error |r − r_exact| at 1.25 periods" noenhanced
set xrange [1e-9:1]
set yrange [1e-13:1e5]
do for [f=1:3] {
    set title heads[f]
    plot for [i=0:counts[f]-1] data."/".word(files, f) index i using 2:4 with linespoints ls (21+i) title columnheader(1)
}
unset key
set yrange [1e-13:10]
set xlabel "evaluations of the right-hand side (the same lines as above)"
set xrange [10:1e7]
set format x "10^{%L}"
do for [f=1:3] {
    set title heads[f]
    plot for [i=0:counts[f]-1] data."/".word(files, f) index i using 3:4 with linespoints ls (21+i) title columnheader(1)
}
unset multiplot
