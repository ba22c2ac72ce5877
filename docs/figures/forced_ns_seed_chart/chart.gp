# A chart written by ss_chart; run `gnuplot chart.gp` in this directory.
# curves.tsv: HB orange, GR red, LP black, PD black dashed, NS magenta, m >= 2 thinner with
# their own dashes; codim2.tsv: SL open circles, the others black dots with labels; response.tsv: the cells by the attractor reached.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 1000,860 enhanced font 'Sans,12'
set output 'chart.png'.suffix
set datafile separator '\t'
set datafile columnheaders
set encoding utf8
set xlabel "forcing frequency Ω" offset 0,0.5
set ylabel "force amplitude A"
set xrange [0.59999999999999998:1.6000000000000001]
set yrange [0.002:0.10000000000000001]
set title "cubic law: β = 0.05, v = 0.42, μ_s = 0.4, μ_m = 0.25, v_m = 0.5"
set rmargin 3
set key outside below center horizontal maxcols 4 width 0 samplen 2 font ',11'
set tics out nomirror front
set border 3 front
array C[5] = [0x08519c, 0x3182bd, 0x8c6d31, 0xc7eae5, 0xd9d9d9]
set label "R1" at 0.95209284364822822,0.0056012896286581773 center front font ',12' noenhanced
set label "R1" at 1.0340741248910748,0.0036860340375502302 center front font ',12' noenhanced
plot 'response.tsv' using 1:2:(0.012625000000000001):(0.0012372500000000001):(C[int($3)+1]) with boxxyerror fs solid 1.0 noborder lc rgb variable notitle, \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#08519c' title "m = 1, no stick", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#3182bd' title "m = 1, 1 stick", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#8c6d31' title "m >= 5", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#c7eae5' title "settling", \
     NaN with boxes fs solid 1.0 border lc rgb '#909090' lc rgb '#d9d9d9' title "quasi-periodic", \
     'curves.tsv' using 1:($4 == 2 ? $2 : NaN) with lines lw 3.5 lc rgb '#c00000' dt 1 title "GR, grazing", \
     'curves.tsv' using 1:($4 == 1 ? $2 : NaN) with lines lw 2.5 lc rgb '#ff00ff' dt (10,4,2,4) title "NS, Neimark-Sacker", \
     'curves.tsv' using 1:($4 == 3 ? $2 : NaN) with lines lw 2.5 lc rgb '#ff00ff' dt (10,4,2,4) notitle, \
     'codim2.tsv' using 2:(strcol(1) ne 'SL' ? $3 : NaN) with points pt 7 ps 1.3 lc rgb 'black' title 'codimension 2'
unset output
