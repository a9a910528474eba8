# SPDX-License-Identifier: BSL-1.0
# Work-precision diagrams of the stiff solvers (bench/stiff_work_precision.cpp and .py): for the problem
# `problem`, the largest relative error at t1 against the evaluations of f (swp_<problem>_evals.png) and against
# the CPU time of one solve (swp_<problem>_time.png), one curve per solver, one point per rtol (1e-4 .. 1e-10,
# half decades; runs that failed are left out). scripts/stiff_work_precision_plot.sh sets `data` (a directory with
# one file <problem>_<solver>.csv per curve, the benchmark's columns), `out` (the PNG directory) and `problem`.
# A solver without a file (SUNDIALS or SciPy missing) is left out.
load "scripts/plots/common.gp"
set terminal pngcairo size 1100,720 font "DejaVu Sans,12"
array key[7] = ["odestep_radau5", "odestep_rodas4", "scipy_radau", "scipy_bdf", "cvode_bdf", "arkode_esdirk43", \
                "arkode_esdirk54"]
array name[7] = ["odestep radau5 (Radau 5(4))", "odestep rodas4 (Rodas4 4(3))", "SciPy Radau", "SciPy BDF", \
                 "CVODE BDF", "ARKODE ESDIRK 4(3)6L", "ARKODE ESDIRK 5(4)8L"]
array colour[7] = ["#ff3030", "#8b0000", "#56a0e0", "#1f4fa0", "#60c060", "#d08ad8", "#a040b0"]
array width[7] = [3.5, 3.5, 1.5, 1.5, 1.5, 1.5, 1.5]
array point[7] = [7, 5, 9, 8, 11, 4, 6]
file(i) = data."/".problem."_".key[i].".csv"
have(i) = system("test -s '".file(i)."' && echo 1 || echo 0") + 0
set logscale xy
set format y "10^{%L}"
set format x "10^{%L}"
set ylabel "largest relative error at t1"
set key outside right top vertical noenhanced
set pointsize 0.9

set output out."/swp_".problem."_evals.png"
set title "Stiff work-precision, ".problem.": error against evaluations of f (rtol = 1e-4 .. 1e-10)" font ",13"
set xlabel "evaluations of f in the solve (exact Jacobian)"
plot for [i=1:7] (have(i) ? file(i) : "") using 5:4 with linespoints lc rgb colour[i] lw width[i] \
     pt point[i] title name[i]

set output out."/swp_".problem."_time.png"
set title "Stiff work-precision, ".problem.": error against CPU time of one solve (minimum)" font ",13"
set xlabel "CPU time of one solve (microseconds; thread CPU clock, SciPy: process time)"
plot for [i=1:7] (have(i) ? file(i) : "") using 10:4 with linespoints lc rgb colour[i] lw width[i] \
     pt point[i] title name[i]
