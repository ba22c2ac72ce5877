# Stability chart written by ss_chart; run `gnuplot chart.gp` in this directory.
# Shading: regions.tsv. Curves: HB black (solid supercritical, dashed subcritical),
# GR red (solid persistence, dashed nonsmooth fold), LP blue. Points: codim2.tsv.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 1100,800 enhanced font ',12'
set output 'chart.png'.suffix
set datafile separator '\t'
set datafile columnheaders
set xlabel 'v' noenhanced
set ylabel 'beta' noenhanced
set xrange [0.02:0.6]
set yrange [0:0.25]
set title 'law=cubic mu_s=0.4 mu_m=0.25 v_m=0.5 k5=0 v=[0.02, 0.6] beta=[0, 0.25]' noenhanced
set key outside right top
set palette defined (0 '#f2f2f2', 1 '#f2f2f2', 1 '#f4a6a6', 2 '#f4a6a6', 2 '#a6c8f4', 3 '#a6c8f4', 3 '#d9b3ef', 4 '#d9b3ef')
set cbrange [-0.5:3.5]
unset colorbox
plot 'regions.tsv' using 1:2:3 with image notitle, \
     NaN with boxes fs solid 1.0 lc rgb '#f2f2f2' title 'steady sliding only', \
     NaN with boxes fs solid 1.0 lc rgb '#f4a6a6' title 'stick-slip', \
     NaN with boxes fs solid 1.0 lc rgb '#a6c8f4' title 'pure-slip oscillation', \
     NaN with boxes fs solid 1.0 lc rgb '#d9b3ef' title 'bistable', \
     'curves.tsv' using 1:(($4 == 1 && (strcol(9) eq 'supercritical') == 1) ? $2 : NaN) with lines lw 2.5 lc rgb 'black' dt 1 title 'HB (dashed: subcritical)', \
     'curves.tsv' using 1:(($4 == 1 && (strcol(9) eq 'supercritical') == 0) ? $2 : NaN) with lines lw 2.5 lc rgb 'black' dt 2 notitle, \
     'curves.tsv' using 1:(($4 == 2 && (strcol(9) eq 'persistence') == 1) ? $2 : NaN) with lines lw 2.5 lc rgb 'red' dt 1 title 'GR (dashed: nonsmooth fold)', \
     'curves.tsv' using 1:(($4 == 2 && (strcol(9) eq 'persistence') == 0) ? $2 : NaN) with lines lw 2.5 lc rgb 'red' dt 2 notitle, \
     'codim2.tsv' using 2:3 with points pt 7 ps 1.5 lc rgb 'black' notitle, \
     'codim2.tsv' using 2:3:1 with labels offset 1.5,0.8 font ',12' notitle
unset output
