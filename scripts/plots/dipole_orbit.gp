# SPDX-License-Identifier: BSL-1.0
# The electron in the dipole field (dipole, 1 GeV, relativistic Boris): one drift round the Earth.
load "scripts/plots/common.gp"
set terminal pngcairo size 1400,720 font "DejaVu Sans,12"
set output out."/dipole_orbit.png"
set multiplot layout 1,2 title "A 1 GeV electron in the Earth's dipole field from 2 Earth radii, pitch angle 30°, relativistic Boris pusher\n(the gyroradius is 0.12 Earth radii; one drift round the Earth, 150 re/c = 3.2 s)" font ",13"
set size ratio -1
set parametric
set trange [0:2*pi]
set samples 200
unset key
set title "seen along the dipole: gyration and the eastward drift"
set xlabel "x (Earth radii)"
set ylabel "y (Earth radii)"
set xrange [-2.6:2.6]
set yrange [-2.6:2.6]
plot data."/dipole_orbit.csv" using 2:3 with lines lc rgb "#1f77b4" lw 0.6, \
     cos(t), sin(t) with filledcurves lc rgb "#88aa88" fs solid 0.6
set title "the meridian plane: bouncing between mirror points"
set xlabel "distance from the axis (Earth radii)"
set ylabel "z (Earth radii)"
set xrange [0:2.6]
set yrange [-1.3:1.3]
set trange [-pi/2:pi/2]
# the field line of the starting shell, r = L cos^2(latitude)
L = 2.06
plot data."/dipole_orbit.csv" using (sqrt($2*$2 + $3*$3)):4 with lines lc rgb "#1f77b4" lw 0.6, \
     L*cos(t)**3, L*cos(t)**2*sin(t) with lines lc rgb "#d62728" dt 2 lw 2, \
     cos(t), sin(t) with filledcurves x1=0 lc rgb "#88aa88" fs solid 0.6
unset multiplot
