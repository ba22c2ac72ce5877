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
set key outside below center horizontal box lc rgb '#c0c0c0' samplen 3 spacing 1.1 height 0.5
set bmargin 7
set style textbox opaque noborder margins 1,1
set output 'resonance.png'
set title "cubic law: β = 0.05, v = 0.25, μ_s = 0.4, μ_m = 0.25, v_m = 0.5, A = 0.3"
set xlabel "forcing frequency Ω (over the natural one)"
set ylabel 'largest displacement x_{max} (dimensionless)'
set yrange [0:*]
set autoscale xfix
c(name) = column(name)
in(b, k, s) = c('branch') == b && strcol('kind') eq k && c('stable') == s
# a style's rows, and the row after each of its runs (no gap at a change)
sel(b, k, s) = (cur = in(b, k, s), out = (cur || (prev && c('branch') == b)) ? c('x_max') : 1/0, prev = cur, out)
plot \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'non-stop', 1)) with lines ls 3 title 'non-stop, stable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'non-stop', 0)) with lines ls 4 title 'non-stop, unstable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'stick-slip', 1)) with lines ls 1 title 'stick-slip, stable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'stick-slip', 0)) with lines ls 2 title 'stick-slip, unstable', \
  'special_points.tsv' using 'omega':'x_max' with points ls 8 notitle, \
  'special_points.tsv' using 'omega':(int($0) % 2 == 0 ? c('x_max') : 1/0):'lab' with labels offset 0, 1.2 boxed font ',10' notitle, \
  'special_points.tsv' using 'omega':(int($0) % 2 == 1 ? c('x_max') : 1/0):'lab' with labels offset 0, -1.2 boxed font ',10' notitle
