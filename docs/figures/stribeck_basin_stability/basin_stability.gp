# Basin stability written by ss_basin; run `gnuplot basin_stability.gp` here.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 1000,720 enhanced font 'Sans,12'
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
ul = 1
ut = 1
uv = 1
up = 1
up2 = 1
set output 'basin_stability.png'.suffix
set title "Stribeck law: β = 0.05, μ_s = 0.4, μ_k = 0.25, v_s = 0.5" offset 0, 1
set xlabel "belt speed v (dimensionless)"
set ylabel 'basin stability (fraction of the box)'
set yrange [-0.02:1.02]
set autoscale xfix
set arrow 10 from up*0.5493061443340549, graph 0 to up*0.5493061443340549, graph 1 nohead lc rgb '#808080' lw 1 dt 2 back
set label 10 'HB' at up*0.5493061443340549, graph 1 center offset 0, 0.7 front font ',10'
set arrow 11 from up*0.6519468583211349, graph 0 to up*0.6519468583211349, graph 1 nohead lc rgb '#808080' lw 1 dt 2 back
set label 11 'GR, LP' at up*0.6519468583211349, graph 1 center offset 0, 0.7 front font ',10'
seg(p) = 0 + (p > up*0.6519468583211349)
plot for [s = 0:1] 'basin_stability.tsv' using ($1*up):(seg($1*up) == s ? $2 : NaN) with linespoints ls 5 pt 7 ps 0.5 title (s == 0 ? 'steady sliding' : ''), \
     for [s = 0:1] 'basin_stability.tsv' using ($1*up):(seg($1*up) == s ? $3 : NaN) with linespoints ls 1 pt 7 ps 0.5 title (s == 0 ? 'stick-slip' : ''), \
     for [s = 0:1] 'basin_stability.tsv' using ($1*up):(seg($1*up) == s ? $4 : NaN) with linespoints ls 3 pt 7 ps 0.5 title (s == 0 ? 'pure slip' : ''), \
     for [s = 0:1] 'basin_stability.tsv' using ($1*up):(seg($1*up) == s ? $5 : NaN) with lines ls 7 title (s == 0 ? 'undecided' : '')
unset output
