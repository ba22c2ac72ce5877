# Seed fig. 6: displacement and velocity against time from (0, 0.25); seed set,
# v = 0.25. The stick phases are the flat stretches x' = v.
# Run from the repository root: gnuplot -e "datadir='build/seed_figures'" plots/fig06_time.gp
if (!exists("datadir")) datadir = "build/seed_figures"
if (!exists("outdir")) outdir = "plots"
data = datadir . "/fig05.tsv"
v = 0.25

set terminal pngcairo size 1100,600 enhanced butt font "Sans,12"
set output outdir . "/fig06_time.png"
set datafile separator "\t"
set title "Seed fig. 6: displacement and velocity from (0, 0.25)\nβ = 0.05, v = 0.25, μ_s = 0.4, μ_m = 0.25, v_m = 0.5 (cubic law)"
set xlabel "time t (dimensionless)"
set ylabel "x, dx/dt (dimensionless)"
set xrange [0:50]
set grid
set key outside right top box
plot v with lines dt 2 lw 1 lc rgb "#888888" title "dx/dt = v", \
     data using 1:2 with lines lw 1.5 lc rgb "#009e73" title "x", \
     data using 1:3 with lines lw 1.5 lc rgb "#0072b2" title "dx/dt", \
     data using 1:(strcol(4) eq "stick" ? $3 : NaN) with lines lw 3 lc rgb "#d62728" title "stick"
