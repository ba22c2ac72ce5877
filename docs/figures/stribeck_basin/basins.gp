# Basins written by ss_basin; run `gnuplot basins.gp` in this directory.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 1000,900 enhanced font 'Sans,12'
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
set output 'basins.png'.suffix
set title "Stribeck law: β = 0.05, v = 0.6, μ_s = 0.4, μ_k = 0.25, v_s = 0.5"
ul = 1
ut = 1
uv = 1
up = 1
up2 = 1
set xlabel "initial displacement x (dimensionless)"
set ylabel "initial velocity dx/dt (dimensionless)"
set xrange [-0.8317013249398576:1.2947760223904903]
set yrange [-0.931555092145677:0.9244180737057345]
unset grid
set palette defined (-0.5 '#d9d9d9', 0.5 '#d9d9d9', 0.5 '#a6cee3', 1.5 '#a6cee3', 1.5 '#fdbf6f', 2.5 '#fdbf6f', 2.5 '#ffffff', 3.5 '#ffffff')
set cbrange [-0.5:3.5]
unset colorbox
fate(s) = s eq 'steady-sliding' ? 0 : s eq 'stick-slip' ? 1 : s eq 'pure-slip' ? 2 : 3
set arrow from -0.46,0.6 to 0.34,0.6 nohead lw 4 lc rgb 'black' front
set bmargin 9
plot 'basins.tsv' using ($1*ul):($2*uv):(fate(strcol(3))) with image notitle, \
     NaN with boxes fs solid border lc rgb '#808080' lc rgb '#d9d9d9' title 'basin: steady sliding', \
     NaN with boxes fs solid border lc rgb '#808080' lc rgb '#a6cee3' title 'basin: stick-slip', \
     NaN with lines lw 4 lc rgb 'black' title 'stick band (dx/dt = v)', \
     'orbits.tsv' using ($4*ul):($1 == 0 ? $5*uv : NaN) with lines ls 1 lw 3 title 'stick-slip orbit, stable', \
     'orbits.tsv' using ($4*ul):($1 == 1 ? $5*uv : NaN) with lines ls 4 lw 3 title 'pure slip orbit, unstable', \
     '+' using (0.2951791317868303):(0) every ::0::0 with points pt 7 ps 1.5 lc rgb 'black' title 'steady sliding (x̄, 0)'
unset output
