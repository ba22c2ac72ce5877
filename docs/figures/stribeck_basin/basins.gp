# Basins written by ss_basin; run `gnuplot basins.gp` in this directory.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 1000,800 enhanced font ',12'
set output 'basins.png'.suffix
set datafile separator '\t'
set datafile columnheaders
set title 'law=stribeck beta=0.05 v=0.6 mu_s=0.4 mu_k=0.25 v_s=0.5' noenhanced
set xlabel 'x'
set ylabel "x'"
set xrange [-0.8317013249398576:1.29477602239049]
set yrange [-0.931555092145677:0.9244180737057345]
set key outside right top
set palette defined (-0.5 '#9ecae1', 0.5 '#9ecae1', 0.5 '#fdae6b', 1.5 '#fdae6b', 1.5 '#a1d99b', 2.5 '#a1d99b', 2.5 '#d9d9d9', 3.5 '#d9d9d9')
set cbrange [-0.5:3.5]
unset colorbox
fate(s) = s eq 'steady-sliding' ? 0 : s eq 'stick-slip' ? 1 : s eq 'pure-slip' ? 2 : 3
set arrow from -0.46,0.6 to 0.34,0.6 nohead lw 4 lc rgb 'black' front
plot 'basins.tsv' using 1:2:(fate(strcol(3))) with image notitle, \
     NaN with boxes fs solid lc rgb '#9ecae1' title 'steady sliding', \
     NaN with boxes fs solid lc rgb '#fdae6b' title 'stick-slip', \
     NaN with boxes fs solid lc rgb '#a1d99b' title 'pure slip', \
     NaN with boxes fs solid lc rgb '#d9d9d9' title 'undecided', \
     NaN with lines lw 4 lc rgb 'black' title 'stick band', \
     'orbits.tsv' using 4:($1 == 0 ? $5 : NaN) with lines lw 3 dt 1 lc rgb 'black' title 'stick-slip (stable)', \
     'orbits.tsv' using 4:($1 == 1 ? $5 : NaN) with lines lw 3 dt 2 lc rgb 'red' title 'pure-slip (unstable)', \
     '+' using (0.2951791317868303):(0) every ::0::0 with points pt 7 ps 1.5 lc rgb 'black' title 'steady sliding (xbar, 0)'
unset output
