# Seed fig. 10: displacement and velocity at v = 0.45 from (0, 0.45): one stick
# phase, then oscillations decaying slowly (2β + μ'(v) = 0.0145) to steady sliding.
# Top: the whole run; bottom: its start, where the stick phase is flat at x' = v.
# Run from the repository root: gnuplot -e "datadir='build/seed_figures'" plots/fig10_time.gp
if (!exists("datadir")) datadir = "build/seed_figures"
if (!exists("outdir")) outdir = "plots"
data = datadir . "/fig09.tsv"
v = 0.45; mu_s = 0.4; k1 = 0.45; k3 = 0.6
x_bar = mu_s - k1*v + k3*v**3   # steady sliding, design notes section 1

set terminal pngcairo size 1100,900 enhanced butt font "Sans,12"
set output outdir . "/fig10_time.png"
set datafile separator "\t"
set multiplot layout 2,1 title "Seed fig. 10: displacement and velocity at v = 0.45 from (0, 0.45)\nβ = 0.05, μ_s = 0.4, μ_m = 0.25, v_m = 0.5 (cubic law)"
set grid
set key outside right top box
set ylabel "x, dx/dt (dimensionless)"
set xlabel "time t (dimensionless)"
set title "the whole run: decay to steady sliding x = x̄ = 0.2522"
plot v with lines dt 2 lw 1 lc rgb "#888888" title "dx/dt = v", \
     x_bar with lines dt 3 lw 1.5 lc rgb "#ff7f0e" title "x = x̄", \
     data using 1:2 with lines lw 1 lc rgb "#009e73" title "x", \
     data using 1:3 with lines lw 1 lc rgb "#0072b2" title "dx/dt", \
     data using 1:(strcol(4) eq "stick" ? $3 : NaN) with lines lw 3 lc rgb "#d62728" title "stick"
set title "the first 30 time units: the stick phase"
set xrange [0:30]
replot
unset multiplot
