# The bifurcation figure of ss_continue --system: x1's extremes, the period and the largest |multiplier| against v.
set terminal pngcairo size 1000,560 enhanced font 'Sans,12'
set encoding utf8
set datafile separator '\t'
set datafile columnheaders
set grid lc rgb '#e0e0e0' lw 0.5
set border lw 1
set style line 1 lc rgb '#0072b2' lw 2 dt 1
set style line 2 lc rgb '#0072b2' lw 2 dt 2
set style line 3 lc rgb '#d55e00' lw 2 dt 1
set style line 4 lc rgb '#d55e00' lw 2 dt 2
set style line 5 lc rgb '#606060' lw 2 dt 1
set style line 6 lc rgb '#606060' lw 2 dt 2
set style line 7 lc rgb '#000000' lw 1 dt 3
set style line 8 lc rgb '#000000' pt 7 ps 1.0
set style line 9 lc rgb '#000000' lw 2.5 dt 1
set style line 10 lc rgb '#009e73' lw 2 dt 2
set style line 11 lc rgb '#cc79a7' lw 2 dt 4
set style line 12 lc rgb '#e69f00' lw 2 dt 5
set key outside below center horizontal box lc rgb '#c0c0c0' samplen 3 spacing 1.1 height 0.5
set bmargin 7
set style textbox opaque noborder margins 1,1
set output 'bifurcation.png'
c(name) = column(name)
stats 'branch.tsv' using 1 nooutput
N = STATS_records
array P[N]
do for [i = 1:N] { P[i] = 0 }
stats 'special_points.tsv' using (P[int(c('pt'))] = 1, 0) nooutput
sel(b, k, s) = c('branch') == b && strcol('kind') eq k && (c('stable') == s || P[int(c('pt'))])
set multiplot layout 1, 1 title "chain: v=[continued] kc=0.5 β=0.05 m1=1 c1=0.1 k1=1 mu\\_s1=0.4 m2=1 c2=0.1 k2=1 mu\\_s2=0.4 m3=1\nc3=0.1 k3=1 mu\\_s3=0.4 m4=1 c4=0.1 k4=1 mu\\_s4=0.4 m5=1 c5=0.1 k5=1 mu\\_s5=0.4 m6=1 c6=0.1 k6=1\nmu\\_s6=0.4 m7=1 c7=0.1 k7=1 mu\\_s7=0.4 m8=1 c8=0.1 k8=1 mu\\_s8=0.4 m9=1 c9=0.1 k9=1 mu\\_s9=0.4 m10=1\nc10=0.1 k10=1 mu\\_s10=0.4"
set xlabel "v"
set autoscale xfix
set ylabel "x1 (min and max)"
set offsets 0, 0, graph 0.12, graph 0.05
plot 'branch.tsv' using 'v':(sel(0, 'equilibrium', 0) ? c('x1_max') : 1/0) with lines ls 6 title 'equilibrium, unstable', \
  'branch.tsv' using 'v':(sel(0, 'equilibrium', 0) ? c('x1_min') : 1/0) with lines ls 6 notitle, \
  'branch.tsv' using 'v':(sel(0, 'equilibrium', 1) ? c('x1_max') : 1/0) with lines ls 5 title 'equilibrium, stable', \
  'branch.tsv' using 'v':(sel(0, 'equilibrium', 1) ? c('x1_min') : 1/0) with lines ls 5 notitle, \
  'special_points.tsv' using 'v':'x1_max' with points ls 8 notitle, \
  'special_points.tsv' using 'v':(int($0) % 2 == 0 ? c('x1_max') : 1/0):'lab' with labels offset 0, 1.2 boxed font ',10' notitle
unset multiplot
