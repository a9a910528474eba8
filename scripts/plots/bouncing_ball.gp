# SPDX-License-Identifier: BSL-1.0
# The bouncing ball (bouncing_ball, run (b): restitution 0.7, RK4 dt = 0.01 s, the floor as an event).
load "scripts/plots/common.gp"
set terminal pngcairo size 1000,550 font "DejaVu Sans,12"
set output out."/bouncing_ball.png"
set title "A ball dropped from 1 m, restitution 0.7: every impact located by the floor event (RK4, dt = 0.01 s)" font ",13"
set xlabel "t (s)"
set ylabel "height y (m)"
set xrange [0:3]
set yrange [-0.02:1.05]
set key top right
plot data."/bouncing_ball.csv" using 1:2 with lines ls 1 title "height (the integrator's steps and impacts)", \
     data."/bouncing_ball.csv" using 1:($2 < 1e-9 && abs($3) > 1e-9 ? $2 : NaN) with points pt 7 ps 0.9 lc rgb "#d62728" title "impacts (the event's time and state)"
