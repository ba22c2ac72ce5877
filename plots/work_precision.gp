# Work-precision diagram of the seed branch (issue 6): error against wall time,
# log-log. Data: work_precision.tsv written by ss_bench, which runs this script
# with the output directory as working directory. By hand, from that directory:
#   gnuplot /path/to/plots/work_precision.gp
# Columns: 1 method, 2 rtol, 3 eps, 5 time_s (median: ours = Continue() + the
# 8 orbits), 8 time_eval_s (ours: the 8 orbits alone), 11 err_period (relative),
# 12 err_xmax (absolute); both errors are maxima over the fixed v set.
if (!exists("suffix")) suffix = ""
data = "work_precision.tsv"
set terminal pngcairo size 1500,800 enhanced font "Sans,11"
set output "work_precision.png" . suffix
set datafile separator "\t"
set datafile columnheaders
set datafile missing "nan"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set bmargin 8
set key box opaque samplen 2 spacing 1.2 font ",10"
set xlabel "wall time [s] (median)"
set xrange [1e-4:*]

is(m, col) = strcol(1) eq m ? column(col) : NaN
rlab(m) = strcol(1) eq m ? sprintf("%.0e", column(2)) : ""
elab(m) = strcol(1) eq m ? sprintf("ε=%.0e", column(3)) : ""

set multiplot layout 1,2 title "stickslip work-precision: seed set, cubic law; orbits at v = 0.05 0.1 0.2 0.3 0.35 0.39 0.42 0.44 (ss\\_bench)" font ",13"
do for [panel = 1:2] {
  ecol = panel == 1 ? 11 : 12
  set ylabel (panel == 1 ? "max relative period error" : "max absolute x_{max} error")
  set title (panel == 1 ? "period" : "x_{max}")
  unset arrow
  unset label
  # One key for both panels, centred under them.
  if (panel == 1) {
    set key horizontal Left reverse maxcols 3 at screen 0.5, screen 0.02 center bottom
  } else {
    unset key
  }
  if (panel == 1) {
    set arrow from graph 0, first 1e-8 to first 0.05, first 1e-8 nohead dt 2 lc rgb "#555555"
    set arrow from first 0.05, graph 0 to first 0.05, first 1e-8 nohead dt 2 lc rgb "#555555"
    set label "target: full branch,\nerr < 10^{-8} in < 50 ms" at graph 0.02, first 1e-9 font ",9" tc rgb "#555555"
  }
  plot data using (is("ours-taylor", 5)):(is("ours-taylor", ecol)) with linespoints lw 2 pt 9 lc rgb "#2ca02c" title "ours, Taylor: branch + 8 orbits", \
       data using (is("ours-taylor", 8)):(is("ours-taylor", ecol)) with linespoints lw 1.5 dt 2 pt 8 lc rgb "#2ca02c" title "ours, Taylor: 8 orbits only", \
       data using (is("ours-adams", 5)):(is("ours-adams", ecol)) with linespoints lw 2 pt 7 lc rgb "#1f77b4" title "ours, Adams: branch + 8 orbits", \
       data using (is("ours-adams", 5)):(is("ours-adams", ecol)):(rlab("ours-adams")) with labels left offset 0.7,0 font ",8" tc rgb "#1f77b4" notitle, \
       data using (is("ours-adams", 8)):(is("ours-adams", ecol)) with linespoints lw 1.5 dt 2 pt 6 lc rgb "#1f77b4" title "ours, Adams: 8 orbits only", \
       data using (is("ours-bdf", 5)):(is("ours-bdf", ecol)) with linespoints lw 2 pt 5 lc rgb "#ff7f0e" title "ours, BDF: branch + 8 orbits", \
       data using (is("brute-adams", 5)):(is("brute-adams", ecol)) with linespoints lw 2 pt 9 lc rgb "#d62728" title "brute force (Filippov, from rest)", \
       data using (is("brute-adams", 5)):(is("brute-adams", ecol)):(rlab("brute-adams")) with labels offset 0,-0.9 font ",8" tc rgb "#d62728" notitle, \
       data using (is("regularised-bdf", 5)):(is("regularised-bdf", ecol)) with linespoints lw 2 pt 11 lc rgb "#9467bd" title "tanh-regularised (BDF, shooting)", \
       data using (is("regularised-bdf", 5)):(is("regularised-bdf", ecol)):(elab("regularised-bdf")) with labels right offset -0.7,0 font ",8" tc rgb "#9467bd" notitle
}
unset multiplot
