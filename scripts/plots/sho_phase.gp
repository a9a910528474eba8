# SPDX-License-Identifier: BSL-1.0
# The harmonic oscillator's phase space (phase_space, problem 3.3): dt = 0.1, 188 steps (3 periods).
load "scripts/plots/common.gp"
set terminal pngcairo size 900,800 font "DejaVu Sans,12"
set output out."/sho_phase.png"
set title "Oscillator x'' = −x from (1, 0), dt = 0.1, 3 periods: phase space (problem 3.3)" font ",13"
set size ratio -1
set xlabel "x"
set ylabel "v"
set xrange [-2.8:2.8]
set yrange [-2.8:2.8]
set key below
plot data."/sho_phase.csv" index 0 using 2:3 with lines ls 2 title "Euler: x² + v² × (1 + dt²) per step", \
     "" index 1 using 2:3 with lines ls 1 title "Euler-Cromer: x² + v² − dt x v kept", \
     "" index 2 using 2:3 with points pt 7 ps 0.4 lc rgb "#2ca02c" title "velocity Verlet: (1 − dt²/4) x² + v² kept", \
     "" index 3 using 2:3 with lines lc rgb "#000000" dt 2 lw 1.5 title "exact: the unit circle"
