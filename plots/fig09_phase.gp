# Seed fig. 9: belt speed v = 0.45, above the Hopf point v_{max} = 0.44096: the
# trajectory from (0, 0.45) sticks once, then spirals into steady sliding.
# Run from the repository root: gnuplot -e "datadir='build/seed_figures'" plots/fig09_phase.gp
if (!exists("datadir")) datadir = "build/seed_figures"
if (!exists("outdir")) outdir = "plots"
data = datadir . "/fig09.tsv"
beta = 0.05; v = 0.45; mu_s = 0.4; x_start = 0; xdot_start = 0.45
k1 = 0.45; k3 = 0.6
x_bar = mu_s - k1*v + k3*v**3   # steady sliding, design notes section 1

set terminal pngcairo size 900,700 enhanced butt font "Sans,12"
set output outdir . "/fig09_phase.png"
set datafile separator "\t"
# The stick set Omega: x' = v, |x + 2 beta v| <= mu_s.
set print $omega
print sprintf("%.17g\t%.17g", -mu_s - 2*beta*v, v)
print sprintf("%.17g\t%.17g", mu_s - 2*beta*v, v)
unset print
set title "Seed fig. 9: v = 0.45 > v_{max} = 0.441, from (0, 0.45) to steady sliding\nβ = 0.05, μ_s = 0.4, μ_m = 0.25, v_m = 0.5 (cubic law)"
set xlabel "displacement x (dimensionless)"
set ylabel "velocity dx/dt (dimensionless)"
set grid
set key outside below center horizontal box
set bmargin 8
plot $omega using 1:2 with lines lw 10 lc rgb "#f4a6a6" title "stick set Ω", \
     data using 2:3 with lines lw 1 lc rgb "#0072b2" title "trajectory (slip)", \
     data using 2:(strcol(4) eq "stick" ? $3 : NaN) with lines lw 3 lc rgb "#d62728" title "stick phase", \
     "+" using (x_start):(xdot_start) every ::0::0 with points pt 7 ps 1.5 lc rgb "black" title "start (0, 0.45)", \
     "+" using (x_bar):(0) every ::0::0 with points pt 6 ps 2 lw 2 lc rgb "#ff7f0e" title sprintf("steady sliding (%.4f, 0)", x_bar)
