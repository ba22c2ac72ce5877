# Basins written by ss_basin; run `gnuplot basins.gp` in this directory.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 1000,800 enhanced font ',12'
set output 'basins.png'.suffix
set datafile separator '\t'
set title 'law=cubic beta=0.05 v=0.25 mu_s=0.4 mu_m=0.25 v_m=0.5 k5=0' noenhanced
set xlabel 'x'
set ylabel "x'"
set xrange [-0.7026792592748364:0.8859044100649252]
set yrange [-0.48291828403530845:0.40524870055920326]
set key outside right top
set palette defined (-0.5 '#9ecae1', 0.5 '#9ecae1', 0.5 '#fdae6b', 1.5 '#fdae6b', 1.5 '#a1d99b', 2.5 '#a1d99b', 2.5 '#d9d9d9', 3.5 '#d9d9d9')
set cbrange [-0.5:3.5]
unset colorbox
fate(s) = s eq 'steady-sliding' ? 0 : s eq 'stick-slip' ? 1 : s eq 'pure-slip' ? 2 : 3
set arrow from -0.42500000000000004,0.25 to 0.375,0.25 nohead lw 4 lc rgb 'black' front
plot 'basins.tsv' using 1:2:(fate(strcol(3))) with image notitle, \
     NaN with boxes fs solid lc rgb '#9ecae1' title 'steady sliding', \
     NaN with boxes fs solid lc rgb '#fdae6b' title 'stick-slip', \
     NaN with boxes fs solid lc rgb '#a1d99b' title 'pure slip', \
     NaN with boxes fs solid lc rgb '#d9d9d9' title 'undecided', \
     NaN with lines lw 4 lc rgb 'black' title 'stick band', \
     'orbits.tsv' using 4:($1 == 0 ? $5 : NaN) with lines lw 3 dt 1 lc rgb 'black' title 'stick-slip (stable)', \
     '+' using (0.296875):(0) every ::0::0 with points pt 7 ps 1.5 lc rgb 'black' title 'steady sliding (xbar, 0)'
unset output
