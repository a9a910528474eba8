# SPDX-License-Identifier: BSL-1.0
# Work-precision diagrams of the adaptive solvers (bench/work_precision.cpp): for the problem `problem`, the
# error at the end against the evaluations of f (wp_<problem>_evals.png) and against the CPU time of a run
# (wp_<problem>_time.png), one curve per solver, one point per tolerance (1e-3 .. 1e-12, half decades).
# scripts/work_precision_plot.sh sets `data` (a directory with one file <problem>_<solver>.csv per curve, the
# benchmark's columns), `out` (the PNG directory) and `problem`. A solver without a file (ARKODE built
# without SUNDIALS) is left out.
load "scripts/plots/common.gp"
set terminal pngcairo size 1100,720 font "DejaVu Sans,12"
array key[9] = ["odestep_dp54", "odestep_dop853", "odeint_dopri5", "odeint_dopri5_dense", "gsl_rkf45", "gsl_rk8pd", \
                "arkode_dp45", "arkode_verner65", "arkode_fehlberg78"]
array name[9] = ["odestep DP 5(4)", "odestep DOP853", "Odeint dopri5 (controlled)", "Odeint dopri5 (dense output)", \
                 "GSL rkf45", "GSL rk8pd", "ARKODE DP 5(4)", "ARKODE Verner 6(5)", "ARKODE Fehlberg 7(8)"]
# odestep thick; a colour per library, light for order 5, dark for order 8.
array colour[9] = ["#ff3030", "#8b0000", "#56a0e0", "#1f4fa0", "#60c060", "#006400", "#d08ad8", "#a040b0", "#4b0082"]
array width[9] = [3.5, 3.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5]
array dash[9] = [1, 1, 1, 2, 1, 1, 1, 1, 1]
array point[9] = [7, 5, 9, 8, 11, 13, 4, 6, 10]
file(i) = data."/".problem."_".key[i].".csv"
have(i) = system("test -s '".file(i)."' && echo 1 || echo 0") + 0
set logscale xy
set format y "10^{%L}"
set format x "10^{%L}"
set ylabel "error at the end: max_i |y_i - y_i,ref|"
set key outside right top vertical noenhanced
set pointsize 0.9

set output out."/wp_".problem."_evals.png"
set title "Work-precision, ".problem.": error against evaluations of f (rtol = atol = 1e-3 .. 1e-12)" font ",13"
set xlabel "evaluations of f in the run (first-step estimate included)"
plot for [i=1:9] (have(i) ? file(i) : "") using 5:4 with linespoints lc rgb colour[i] lw width[i] dt dash[i] \
     pt point[i] title name[i]

set output out."/wp_".problem."_time.png"
set title "Work-precision, ".problem.": error against CPU time of one run (median)" font ",13"
set xlabel "CPU time of one run (microseconds; thread CPU clock, median of the repeats)"
plot for [i=1:9] (have(i) ? file(i) : "") using 6:4 with linespoints lc rgb colour[i] lw width[i] dt dash[i] \
     pt point[i] title name[i]
