# Basins on the stroboscopic section (forcing phase 0) of ss_basin --force.
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
attractor	x	xdot
0	0.5459472018642053	0.15307424006987777
0	0.8629902816329925	0.09645976634001734
EOD
set output 'basins_forced.png'
set title "cubic law: β = 0.05, v = 0.25, μ_s = 0.4, μ_m = 0.25, v_m = 0.5, A = 0.3, Ω = 0.559"
set xlabel "displacement x at forcing phase 0 (dimensionless)"
set ylabel "velocity x' at forcing phase 0 (dimensionless)"
unset grid
set bmargin 8.5
set xrange [-1.51875:1.51875]
set yrange [-1.51875:1.51875]
set style fill solid 1.0 noborder
plot 'basins_forced.tsv' using 'x':(column('attractor') == 0 ? column('xdot') : 1/0):(0.019125):(0.019125) with boxxyerror lc rgb '#0072b2' title "period 2, 2 sticks, x = 0.546 (4393 starts)", \
     'basins_forced.tsv' using 'x':(column('attractor') == 1 ? column('xdot') : 1/0):(0.019125):(0.019125) with boxxyerror lc rgb '#000000' title "chaotic, 0.66 sticks/period (2168 starts)", \
     $cycles using 'x':'xdot' with points pt 7 ps 1.4 lc rgb 'white' notitle, \
     $cycles using 'x':'xdot' with points pt 6 ps 1.4 lw 2 lc rgb 'black' title 'the m section points of each periodic attractor'
