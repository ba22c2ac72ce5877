# A chart written by ss_chart; run `gnuplot chart.gp` in this directory.
# curves.tsv: HB orange, GR red, LP black, PD black dashed, NS magenta, m >= 2 thinner with
# their own dashes; codim2.tsv: SL open circles, the others black dots with labels; response.tsv: the cells by the attractor reached.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 1000,860 enhanced font 'Sans,12'
set output 'chart.png'.suffix
set datafile separator '\t'
set datafile columnheaders
set encoding utf8
set xlabel "belt speed v" offset 0,0.5
set ylabel "kc"
set xrange [0.10000000000000001:0.5]
set yrange [0.10000000000000001:1]
set title "chain: β = 0.05, m1 = 1, c1 = 0.1, k1 = 1, mu\\_s1 = 0.4, m2 = 1.3, c2 = 0.1, k2 = 1, mu\\_s2 = 0.4"
set rmargin 3
set key outside below center horizontal maxcols 4 width 0 samplen 2 font ',11'
set tics out nomirror front
set border 3 front
array C[15] = [0x08519c, 0x3182bd, 0x6baed6, 0x006d2c, 0x31a354, 0x74c476, 0x54278f, 0x756bb1, 0x9e9ac8, 0xcbc9e2, 0x8c6d31, 0xffffff, 0xc7eae5, 0xd9d9d9, 0x404040]
plot 'response.tsv' using 1:2:(0.0063125000000000004):(0.014203125):(C[int($3)+1]) with boxxyerror fs solid 1.0 noborder lc rgb variable notitle, \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#08519c' title "m = 1, no stick", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#3182bd' title "m = 1, 1 stick", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#6baed6' title "m = 1, 2 sticks", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#006d2c' title "m = 2, 2 sticks", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#31a354' title "m = 2, 3 sticks", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#74c476' title "m = 2, 4 sticks", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#54278f' title "m = 4, no stick", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#756bb1' title "m = 4, 6 sticks", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#9e9ac8' title "m = 4, 7 sticks", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#cbc9e2' title "m = 4, 8 sticks", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#8c6d31' title "m >= 5", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#ffffff' title "rest", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#c7eae5' title "settling", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#d9d9d9' title "quasi-periodic", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#404040' title "chaotic", \
     'curves.tsv' using 1:($4 == 1 ? $2 : NaN) with lines lw 3.5 lc rgb '#e66100' dt 1 title "HB of steady sliding", \
     'curves.tsv' using 1:($4 == 3 ? $2 : NaN) with lines lw 2.5 lc rgb 'black' dt 1 title "LP, fold", \
     'curves.tsv' using 1:($4 == 4 ? $2 : NaN) with lines lw 2.5 lc rgb 'black' dt (8,4) title "PD, period doubling", \
     'curves.tsv' using 1:($4 == 2 ? $2 : NaN) with lines lw 2.5 lc rgb '#ff00ff' dt (10,4,2,4) title "NS, Neimark-Sacker", \
     'codim2.tsv' using 2:(strcol(1) eq 'SL' ? $3 : NaN) with points pt 6 ps 1.6 lw 2 lc rgb 'black' title 'SL, sliding end'
unset output
