# The resonance figure of ss_continue (forced oscillator): x_max against omega.
set terminal pngcairo size 1000,650 enhanced font ',11'
set output 'resonance.png'
set datafile separator '\t'
set title "law=coulomb beta=0.05 v=0 mu_s=0.4 mu_k=0.3 force=0.7 omega=[0.3, 2.5]" noenhanced
set xlabel '{/Symbol W} (forcing / natural frequency)'
set ylabel 'x_{max}'
set grid
set key top right box opaque
set yrange [0:*]
c(name) = column(name)
in(b, k, s) = c('branch') == b && strcol('kind') eq k && c('stable') == s
# a style's rows, and the row after each of its runs (no gap at a change)
sel(b, k, s) = (cur = in(b, k, s), out = (cur || (prev && c('branch') == b)) ? c('x_max') : 1/0, prev = cur, out)
plot \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'non-stop', 1)) with lines lw 2.5 dt 1 lc rgb '#1f5fbf' title 'non-stop, stable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'non-stop', 0)) with lines lw 1.8 dt 2 lc rgb '#1f5fbf' title 'non-stop, unstable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'stick-slip', 1)) with lines lw 2.5 dt 1 lc rgb '#c0392b' title 'stick-slip, stable', \
  prev = 0, 'branch.tsv' using 'omega':(sel(1, 'stick-slip', 0)) with lines lw 1.8 dt 2 lc rgb '#c0392b' title 'stick-slip, unstable'
