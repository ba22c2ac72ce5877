# The orbit diagram of ss_orbit_diagram: section points (forcing phase 0) and
# the largest Lyapunov exponent against omega.
set terminal pngcairo size 1100,900 enhanced font 'Sans,12'
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
set output 'orbit_diagram.png'
set multiplot
set autoscale xfix
set lmargin 12
set rmargin 4
unset key
sel(d, col) = strcol('direction') eq d ? column(col) : 1/0
set size 1, 0.62
set origin 0, 0.38
set tmargin 3
set bmargin 0.5
set title "cubic law: β = 0.05, v = 0.25, μ_s = 0.4, μ_m = 0.25, v_m = 0.5, A = 0.3"
set format x ''
set ylabel "displacement x at forcing phase 0"
plot 'orbit_diagram.tsv' using (sel('down', 'omega')):'x' with points pt 7 ps 0.25 lc rgb '#d55e00' title 'sweep down', \
     'orbit_diagram.tsv' using (sel('up', 'omega')):'x' with points pt 7 ps 0.12 lc rgb '#0072b2' title 'sweep up'
unset title
set size 1, 0.38
set origin 0, 0
set tmargin 0.5
set bmargin 7
set format x '% g'
set xlabel "forcing frequency Ω"
set ylabel 'largest Lyapunov exponent λ_1'
set key outside below center horizontal
plot 0 with lines ls 7 notitle, \
     'lyapunov.tsv' using (sel('down', 'omega')):'lyapunov' with points pt 7 ps 0.35 lc rgb '#d55e00' title 'sweep down', \
     'lyapunov.tsv' using (sel('up', 'omega')):'lyapunov' with points pt 7 ps 0.35 lc rgb '#0072b2' title 'sweep up', \
     'lyapunov.tsv' using 'omega':(column('lyapunov') > 3 * column('lyapunov_err') && column('lyapunov') > 0.001 ? column('lyapunov') : 1/0) with points pt 6 ps 1.2 lw 1.5 lc rgb 'black' title 'chaotic: λ_1 > max(3σ, 0.001)'
unset multiplot
