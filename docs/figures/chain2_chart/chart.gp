# A system's chart written by ss_chart; run `gnuplot chart.gp` in this directory.
# curves.tsv: HB red, LP black, PD black dashed, NS magenta, GR blue; codim2.tsv: SL open
# circles, the others black dots with their labels.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 900,700 enhanced font 'Sans,12'
set output 'chart.png'.suffix
set datafile separator '\t'
set datafile columnheaders
set encoding utf8
set xlabel "v" noenhanced
set ylabel "kc" noenhanced
set xrange [0.10000000000000001:0.5]
set yrange [0.10000000000000001:1]
set title "chain: v=[axis] kc=[axis] β=0.05 m1=1 c1=0.1 k1=1 mu\\_s1=0.4 m2=1.3 c2=0.1 k2=1 mu\\_s2=0.4"
set key outside below horizontal font ',11'
set tics out nomirror
set border 3
set grid lc rgb '#e0e0e0'
plot NaN notitle, \
     'curves.tsv' using 1:($4 == 1 ? $2 : NaN) with lines lw 2.5 lc rgb '#c00000' dt 1 title "HB of steady sliding", \
     'curves.tsv' using 1:($4 == 3 ? $2 : NaN) with lines lw 2.5 lc rgb 'black' dt 1 title "LP, fold", \
     'curves.tsv' using 1:($4 == 4 ? $2 : NaN) with lines lw 2.5 lc rgb 'black' dt (8,4) title "PD, period doubling", \
     'curves.tsv' using 1:($4 == 2 ? $2 : NaN) with lines lw 2.5 lc rgb '#ff00ff' dt (10,4,2,4) title "NS, Neimark-Sacker", \
     'codim2.tsv' using 2:(strcol(1) eq 'SL' ? $3 : NaN) with points pt 6 ps 1.2 lw 1.5 lc rgb 'black' title 'SL, the switching sequence changes'
