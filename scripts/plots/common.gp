# SPDX-License-Identifier: BSL-1.0
# Settings every picture shares; each script loads it, then sets its own size and plots.
# `data` (the CSV directory) and `out` (the PNG directory) come from scripts/plots.sh.
set datafile separator ","
set datafile missing "nan"
set encoding utf8
set grid lc rgb "#dddddd"
set border lc rgb "#444444"
set key box opaque samplen 2 spacing 1.1 noenhanced
set style line 1 lc rgb "#1f77b4" lw 2
set style line 2 lc rgb "#d62728" lw 2
set style line 3 lc rgb "#2ca02c" lw 2
set style line 4 lc rgb "#ff7f0e" lw 2
set style line 5 lc rgb "#9467bd" lw 2
set style line 6 lc rgb "#8c564b" lw 2
set style line 7 lc rgb "#e377c2" lw 2
set style line 8 lc rgb "#7f7f7f" lw 2
set style line 9 lc rgb "#bcbd22" lw 2
set style line 10 lc rgb "#17becf" lw 2
set style line 11 lc rgb "#000000" lw 2
set style line 12 lc rgb "#aec7e8" lw 2
set style line 13 lc rgb "#ff9896" lw 2
set style line 14 lc rgb "#98df8a" lw 2
