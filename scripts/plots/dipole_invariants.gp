# SPDX-License-Identifier: BSL-1.0
# The 10 MeV electron's magnetic moment and |u| (dipole): Boris against RK4 at the same step.
load "scripts/plots/common.gp"
set terminal pngcairo size 1000,700 font "DejaVu Sans,12"
set output out."/dipole_invariants.png"
set multiplot layout 2,1 title "A 10 MeV electron in the dipole field, three bounces (5.4·10^5 steps of 1/40 gyration at the mirror point)" font ",13"
set xlabel "t (Earth radius / c = 21 ms)"
set key bottom left
set title "magnetic moment μ = u_⊥² / |B|, an adiabatic invariant"
set ylabel "μ / μ_0"
plot data."/dipole_invariants.csv" index 0 using 1:2 with lines ls 1 title "Boris", \
     "" index 1 using 1:2 with lines ls 2 title "RK4"
set title "|u| = γ|v|, which a magnetic field cannot change"
set ylabel "|u| / |u_0|"
plot data."/dipole_invariants.csv" index 0 using 1:3 with lines ls 1 title "Boris (at the step times; its half-step |u| is exact)", \
     "" index 1 using 1:3 with lines ls 2 title "RK4"
unset multiplot
