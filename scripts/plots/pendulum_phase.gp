# SPDX-License-Identifier: BSL-1.0
# The pendulum's phase portrait, one panel per method (phase_space: dt = 0.15, 167 steps, five starts).
load "scripts/plots/common.gp"
set terminal pngcairo size 1500,950 font "DejaVu Sans,12"
set output out."/pendulum_phase.png"
wrap(x) = x - 2*pi*floor((x + pi) / (2*pi))
set multiplot layout 2,3 title "Pendulum θ'' = −sin θ, dt = 0.15, t = 0 … 25: phase portrait per method\n(dashed: the exact separatrix ω = ±2 cos(θ/2); θ wrapped to [−π, π))" font ",14"
set xrange [-pi:pi]
set yrange [-3.2:3.2]
set xtics ("−π" -pi, "−π/2" -pi/2, "0" 0, "π/2" pi/2, "π" pi)
set xlabel "θ (rad)"
set ylabel "ω (rad/s)"
unset key
set samples 400
array T[6] = ["Euler: energy grows every step", "Euler-Cromer (symplectic, 1st order)", "midpoint (RK2): energy drifts up", "RK4: drifts down, too slowly to see", "velocity Verlet (symplectic, 2nd order)", "Forest-Ruth (symplectic, 4th order)"]
do for [i=0:5] {
    set title T[i+1]
    plot data."/pendulum_phase.csv" index i using (wrap($2)):3 with points pt 7 ps 0.35 lc rgb "#1f77b4", \
         2*cos(x/2) with lines dt 2 lc rgb "#888888", -2*cos(x/2) with lines dt 2 lc rgb "#888888"
}
unset multiplot
