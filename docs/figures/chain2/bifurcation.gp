# The bifurcation figure of ss_continue --system: x1's extremes, the period and the largest |multiplier| against v.
set terminal pngcairo size 1000,1150 enhanced font 'Sans,12'
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
array X[N]; array B[N]; array K[N]; array S[N]; array D[2*N]; array Y[4*N]
do for [i = 1:4*N] { Y[i] = NaN }
stats 'branch.tsv' using (i = int($0) + 1, X[i] = c('v'), B[i] = c('branch'), K[i] = (strcol('kind') eq 'stick-slip' ? 1 : strcol('kind') eq 'pure-slip' ? 2 : 0), S[i] = c('stable'), 0) nooutput
stats 'branch.tsv' using (Y[0 * N + int($0) + 1] = c('x1_max'), 0) nooutput
stats 'branch.tsv' using (Y[1 * N + int($0) + 1] = c('x1_min'), 0) nooutput
stats 'branch.tsv' using (Y[2 * N + int($0) + 1] = c('period'), 0) nooutput
stats 'branch.tsv' using (Y[3 * N + int($0) + 1] = c('mult_max'), 0) nooutput
owner(i) = P[i + 1] && !P[i] ? i : i + 1
seg(i, k, s) = i >= 1 && i < N && B[i] == B[i + 1] ? (K[owner(i)] == k && S[owner(i)] == s) : 0
row(j) = int((j + 1) / 2)
sel(j, k, s, y) = int(j) % 2 ? (seg(row(j) - 1, k, s) || seg(row(j), k, s) ? Y[y * N + row(j)] : NaN) : (seg(row(j), k, s) ? Y[y * N + row(j)] : NaN)
set multiplot layout 3, 1 title "chain: v=[continued] kc=0.2 β=0.05 m1=1 c1=0.1 k1=1 mu\\_s1=0.4 m2=1 c2=0.1 k2=1 mu\\_s2=0.4"
set xlabel "v"
set autoscale xfix
set ylabel "x1 (min and max)"
set offsets 0, 0, graph 0.12, graph 0.05
plot D using (X[row($1)]):(sel($1, 0, 0, 0)) with lines ls 6 title 'equilibrium, unstable', \
  D using (X[row($1)]):(sel($1, 0, 0, 1)) with lines ls 6 notitle, \
  D using (X[row($1)]):(sel($1, 0, 1, 0)) with lines ls 5 title 'equilibrium, stable', \
  D using (X[row($1)]):(sel($1, 0, 1, 1)) with lines ls 5 notitle, \
  D using (X[row($1)]):(sel($1, 1, 1, 0)) with lines ls 1 title 'stick-slip, stable', \
  D using (X[row($1)]):(sel($1, 1, 1, 1)) with lines ls 1 notitle, \
  'special_points.tsv' using 'v':'x1_max' with points ls 8 notitle, \
  'special_points.tsv' using 'v':(int($0) % 2 == 0 ? c('x1_max') : 1/0):'lab' with labels offset 0, 1.2 boxed font ',10' notitle, \
  'special_points.tsv' using 'v':(int($0) % 2 == 1 ? c('x1_max') : 1/0):'lab' with labels offset 0, -1.2 boxed font ',10' notitle
unset label
set key off
set bmargin 3.5
set offsets 0, 0, graph 0.05, graph 0.05
set ylabel 'period'
plot D using (X[row($1)]):(sel($1, 1, 1, 2)) with lines ls 1 notitle
set ylabel 'largest |Floquet multiplier|'
set yrange [0:*]
plot D using (X[row($1)]):(sel($1, 1, 1, 3)) with lines ls 1 notitle, \
  1 with lines ls 7 notitle
unset multiplot
