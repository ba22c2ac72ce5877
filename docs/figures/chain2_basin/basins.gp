# Basins of ss_basin --system on the slice (x1, x1') through steady sliding.
set terminal pngcairo size 900,900 enhanced font 'Sans,12'
set encoding utf8
set datafile separator '\t'
set datafile columnheaders
set grid lc rgb '#e0e0e0' lw 0.5
set border lw 1
set style line 1 lc rgb '#0072b2' lw 2 dt 1
set style line 2 lc rgb '#0072b2' lw 2 dt 2
set style line 3 lc rgb '#d55e00' lw 2 dt 1
set style line 4 lc rgb '#d55e00' lw 2 dt 2
set style line 5 lc rgb '#606060' lw 2 dt 1
set style line 6 lc rgb '#606060' lw 2 dt 2
set style line 7 lc rgb '#000000' lw 1 dt 3
set style line 8 lc rgb '#000000' pt 7 ps 1.0
set style line 9 lc rgb '#000000' lw 2.5 dt 1
set style line 10 lc rgb '#009e73' lw 2 dt 2
set style line 11 lc rgb '#cc79a7' lw 2 dt 4
set style line 12 lc rgb '#e69f00' lw 2 dt 5
set key outside below center horizontal box lc rgb '#c0c0c0' samplen 3 spacing 1.1 height 0.5
set bmargin 7
set style textbox opaque noborder margins 1,1
$cycles << EOD
attractor	x1	x1dot
0	0.5289613441159889	0
1	0.6500745314396399	0
EOD
set output 'basins.png'
set title "chain: v=0.3 kc=0.5 β=0.05 m1=1 c1=0.1 k1=1 mu\\_s1=0.4 m2=1 c2=0.1 k2=1 mu\\_s2=0.4"
set xlabel "x1 at the start"
set ylabel "x1' at the start"
unset grid
set bmargin 9.5
set xrange [-0.7438:1.3062]
set yrange [-1.025:1.025]
set style fill solid 1.0 noborder
plot 'basins.tsv' using 'x1':(column('attractor') == 0 ? column('x1dot') : 1/0):(0.025500000000000002):(0.025500000000000002) with boxxyerror lc rgb '#0072b2' title "period 1, 2 sticks, x1 = 0.529 (1230 starts)", \
     'basins.tsv' using 'x1':(column('attractor') == 1 ? column('x1dot') : 1/0):(0.025500000000000002):(0.025500000000000002) with boxxyerror lc rgb '#d55e00' title "period 1, 2 sticks, x1 = 0.65 (450 starts)", \
     'basins.tsv' using 'x1':(column('attractor') == 2 ? column('x1dot') : 1/0):(0.025500000000000002):(0.025500000000000002) with boxxyerror lc rgb '#bdbdbd' title "undecided (1 starts)", \
     $cycles using 'x1':'x1dot' with points pt 7 ps 1.4 lc rgb 'white' notitle, \
     $cycles using 'x1':'x1dot' with points pt 6 ps 1.4 lw 2 lc rgb 'black' title 'the m section points of each periodic attractor'
