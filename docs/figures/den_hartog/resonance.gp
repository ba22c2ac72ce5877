# The resonance figure of ss_continue (forced oscillator): x_max against omega.
set terminal pngcairo size 1000,650 enhanced font ',11'
set output 'resonance.png'
set datafile separator '\t'
set title "law=coulomb beta=0 v=0 mu_s=0.3 mu_k=0.3 force=1 omega=[0.75, 2.5]" noenhanced
set xlabel '{/Symbol W} (forcing / natural frequency)'
set ylabel 'x_{max}'
set grid
set key top right box opaque
set yrange [0:*]
c(name) = column(name)
in(b, k, s) = c('branch') == b && strcol('kind') eq k && c('stable') == s
# a style's rows, and the row after each of its runs (no gap at a change)
sel(b, k, s) = (cur = in(b, k, s), out = (cur || (prev && c('branch') == b)) ? c('x_max') : 1/0, prev = cur, out)
set object 1 rect from 0.9766122338634435, graph 0 to 1.0227630451873286, graph 1 fc rgb '#e8e8e8' fs solid noborder behind
set label 1 'not traced: |x| unbounded' at 1.0227630451873286, graph 0.93 offset 1, 0 tc rgb '#555555'
mu = 0.3; A = 1
V(w) = A / (1 - w*w); U(w) = sin(pi/w) / (w * (1 + cos(pi/w)))
D(w) = V(w)**2 - (mu * U(w))**2
DH(w) = D(w) > 0 ? sqrt(D(w)) : 1/0
plot \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'non-stop', 1)) with lines lw 2.5 dt 1 lc rgb '#1f5fbf' title 'non-stop, stable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'non-stop', 0)) with lines lw 1.8 dt 2 lc rgb '#1f5fbf' title 'non-stop, unstable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'stick-slip', 1)) with lines lw 2.5 dt 1 lc rgb '#c0392b' title 'stick-slip, stable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'stick-slip', 0)) with lines lw 1.8 dt 2 lc rgb '#c0392b' title 'stick-slip, unstable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(2, 'non-stop', 1)) with lines lw 2.5 dt 1 lc rgb '#1f5fbf' notitle, \
  prev = 0, 'branch.tsv' using 'omega':(sel(2, 'non-stop', 0)) with lines lw 1.8 dt 2 lc rgb '#1f5fbf' notitle, \
  prev = 0, 'branch.tsv' using 'omega':(sel(2, 'stick-slip', 1)) with lines lw 2.5 dt 1 lc rgb '#c0392b' notitle, \
  prev = 0, 'branch.tsv' using 'omega':(sel(2, 'stick-slip', 0)) with lines lw 1.8 dt 2 lc rgb '#c0392b' notitle, \
  'branch.tsv' using 'omega':(c('branch') == 1 && strcol('kind') eq 'non-stop' ? DH(c('omega')) : 1/0) with lines lw 1 lc rgb 'black' title 'Den Hartog (1931) closed form', \
  'branch.tsv' using 'omega':(c('branch') == 2 && strcol('kind') eq 'non-stop' ? DH(c('omega')) : 1/0) with lines lw 1 lc rgb 'black' notitle
