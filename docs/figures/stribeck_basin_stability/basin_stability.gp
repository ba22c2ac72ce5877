# Basin stability written by ss_basin; run `gnuplot basin_stability.gp` here.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 900,600 enhanced font ',12'
set output 'basin_stability.png'.suffix
set datafile separator '\t'
set datafile columnheaders
set title 'basin stability, law=stribeck beta=0.05 mu_s=0.4 mu_k=0.25 v_s=0.5' noenhanced
set xlabel 'v' noenhanced
set ylabel 'basin stability (fraction of the box)'
set yrange [-0.02:1.02]
set key outside right top
set grid
plot 'basin_stability.tsv' using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#3182bd' title 'steady sliding', \
     '' using 1:3 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#e6550d' title 'stick-slip', \
     '' using 1:4 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#31a354' title 'pure slip', \
     '' using 1:5 with lines lw 1 dt 2 lc rgb 'gray40' title 'undecided'
unset output
