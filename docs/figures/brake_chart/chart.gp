# A chart written by ss_chart; run `gnuplot chart.gp` in this directory.
# curves.tsv: HB orange, GR red, LP black, PD black dashed, NS magenta, m >= 2 thinner with
# their own dashes; codim2.tsv: SL open circles, the others black dots with labels; response.tsv: the cells by the attractor reached.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 1000,860 enhanced font 'Sans,12'
set output 'chart.png'.suffix
set datafile separator '\t'
set datafile columnheaders
set encoding utf8
set xlabel "kinetic friction coefficient μ_k" offset 0,0.5
set ylabel "damping ratio β"
set xrange [0.45000000000000001:0.59999999999999998]
set yrange [0.01:0.029999999999999999]
set title "mode\\_coupling: k11 = 1, k22 = 1.5, k12 = -0.3, gamma = 1, v = 0.5, μ_s = 0.8"
set rmargin 3
set key outside below center horizontal maxcols 4 width 0 samplen 2 font ',11'
set tics out nomirror front
set border 3 front
array C[6] = [0x08519c, 0x3182bd, 0xffffff, 0xc7eae5, 0xd9d9d9, 0xffe066]
set label "CP" at 0.54071115011646276,0.025392413055472879 center front font ',12' noenhanced
plot 'response.tsv' using 1:2:(0.0023671874999999995):(0.00031562499999999993):(C[int($3)+1]) with boxxyerror fs solid 1.0 noborder lc rgb variable notitle, \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#08519c' title "m = 1, no stick", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#3182bd' title "m = 1, 1 stick", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#ffffff' title "rest", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#c7eae5' title "settling", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#d9d9d9' title "quasi-periodic", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#ffe066' title "contact-lost", \
     'curves.tsv' using 1:($4 == 1 ? $2 : NaN) with lines lw 3.5 lc rgb '#e66100' dt 1 title "HB of steady sliding", \
     'curves.tsv' using 1:($4 == 2 ? $2 : NaN) with lines lw 2.5 lc rgb 'black' dt 1 title "LP, fold", \
     'codim2.tsv' using 2:(strcol(1) ne 'SL' ? $3 : NaN) with points pt 7 ps 1.3 lc rgb 'black' title 'codimension 2'
unset output
