# The resonance figure of ss_continue (forced oscillator): x_max against omega.
set terminal pngcairo size 1000,720 enhanced font 'Sans,12'
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
set output 'resonance.png'
set title "cubic law: β = 0.05, v = 0.25, μ_s = 0.4, μ_m = 0.25, v_m = 0.5, A = 0.3"
set xlabel "forcing frequency Ω (over the natural one)"
set ylabel 'largest displacement x_{max} (dimensionless)'
set yrange [0:*]
set offsets 0, 0, graph 0.1, 0  # room above the top point for its label
set autoscale xfix
c(name) = column(name)
stats 'branch.tsv' using 1 nooutput
N = STATS_records
array X[N]; array Y[N]; array B[N]; array K[N]; array S[N]; array P[N]; array D[2*N]
array R[4] = [0, 0, 0, 0]  # rows per style: a key entry only for a drawn style
stats 'branch.tsv' using (i = int($0) + 1, X[i] = c('omega'), Y[i] = c('x_max'), B[i] = c('branch'), K[i] = (strcol('kind') eq 'pure-slip'), S[i] = c('stable'), P[i] = 0, R[1 + 2 * K[i] + S[i]] = R[1 + 2 * K[i] + S[i]] + 1, 0) nooutput
stats 'special_points.tsv' using (P[int(c('pt'))] = 1, 0) nooutput
owner(i) = P[i + 1] && !P[i] ? i : i + 1
seg(i, k, s) = i >= 1 && i < N && B[i] == B[i + 1] ? (K[owner(i)] == k && S[owner(i)] == s) : 0
row(j) = int((j + 1) / 2)
sel(j, k, s) = int(j) % 2 ? (seg(row(j) - 1, k, s) || seg(row(j), k, s) ? Y[row(j)] : NaN) : (seg(row(j), k, s) ? Y[row(j)] : NaN)
plot \
  D using (X[row($1)]):(sel($1, 1, 1)) with lines ls 3 title (R[4] > 0 ? 'pure-slip, stable' : ''), \
  D using (X[row($1)]):(sel($1, 1, 0)) with lines ls 4 title (R[3] > 0 ? 'pure-slip, unstable' : ''), \
  D using (X[row($1)]):(sel($1, 0, 1)) with lines ls 1 title (R[2] > 0 ? 'stick-slip, stable' : ''), \
  D using (X[row($1)]):(sel($1, 0, 0)) with lines ls 2 title (R[1] > 0 ? 'stick-slip, unstable' : ''), \
  'special_points.tsv' using 'omega':'x_max' with points ls 8 notitle, \
  'special_points.tsv' using 'omega':(int($0) % 2 == 0 ? c('x_max') : 1/0):'lab' with labels offset 0, 1.2 boxed font ',10' notitle, \
  'special_points.tsv' using 'omega':(int($0) % 2 == 1 ? c('x_max') : 1/0):'lab' with labels offset 0, -1.2 boxed font ',10' notitle
