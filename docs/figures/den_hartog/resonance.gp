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
set title "Coulomb law: β = 0, v = 0, μ_s = 0.3, μ_k = 0.3, A = 1"
set xlabel "forcing frequency Ω (over the natural one)"
set ylabel 'largest displacement x_{max} (dimensionless)'
set yrange [0:*]
set autoscale xfix
c(name) = column(name)
in(b, k, s) = c('branch') == b && strcol('kind') eq k && c('stable') == s
# a style's rows, and the row after each of its runs (no gap at a change)
sel(b, k, s) = (cur = in(b, k, s), out = (cur || (prev && c('branch') == b)) ? c('x_max') : 1/0, prev = cur, out)
set object 1 rect from 0.9766122338634436, graph 0 to 1.0227630451873284, graph 1 fc rgb '#e8e8e8' fs solid noborder behind
set label 1 'not traced: |x| unbounded' at 1.0227630451873284, graph 0.93 offset 1, 0 tc rgb '#555555'
set bmargin 8.5
mu = 0.3; A = 1
V(w) = A / (1 - w*w); U(w) = sin(pi/w) / (w * (1 + cos(pi/w)))
D(w) = V(w)**2 - (mu * U(w))**2
DH(w) = D(w) > 0 ? sqrt(D(w)) : 1/0
plot \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'non-stop', 1)) with lines ls 3 title 'non-stop, stable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'non-stop', 0)) with lines ls 4 title 'non-stop, unstable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'stick-slip', 1)) with lines ls 1 title 'stick-slip, stable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'stick-slip', 0)) with lines ls 2 title 'stick-slip, unstable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(2, 'non-stop', 1)) with lines ls 3 notitle, \
  prev = 0, 'branch.tsv' using 'omega':(sel(2, 'non-stop', 0)) with lines ls 4 notitle, \
  prev = 0, 'branch.tsv' using 'omega':(sel(2, 'stick-slip', 1)) with lines ls 1 notitle, \
  prev = 0, 'branch.tsv' using 'omega':(sel(2, 'stick-slip', 0)) with lines ls 2 notitle, \
  'branch.tsv' using 'omega':(c('branch') == 1 && strcol('kind') eq 'non-stop' ? DH(c('omega')) : 1/0) with lines lw 1 lc rgb 'black' title 'Den Hartog (1931) closed form', \
  'branch.tsv' using 'omega':(c('branch') == 2 && strcol('kind') eq 'non-stop' ? DH(c('omega')) : 1/0) with lines lw 1 lc rgb 'black' notitle
