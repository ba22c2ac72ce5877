set terminal pngcairo size 1400,650 enhanced font 'Sans,12'
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
set output "trajectory.png"
set bmargin 9
set multiplot layout 1,2 title "cubic law: β = 0.05, v = 0.25, μ_s = 0.4, μ_m = 0.25, v_m = 0.5, A = 0.3, Ω = 0.6"
set offsets 0, 0, graph 0.04, graph 0.04
set xlabel "x"
set ylabel "x'"
set title 'phase portrait'
plot 'trajectory.tsv' using (column('x')):(column('t') < 300 ? column('xdot') : NaN) with lines lw 1 lc rgb '#b0b0b0' title "transient (t < 300)", \
     'trajectory.tsv' using (column('x')):(column('t') >= 300 ? column('xdot') : NaN) with lines ls 1 lw 1.5 title "after the transient (t ≥ 300)", \
     'trajectory.tsv' using (column('x')):(substr(strcol('mode'), 1, 5) eq 'stick' ? column('xdot') : NaN) with lines ls 9 title "sticking"
set offsets 0, 0, 0, 0
set xlabel 'time t'
set ylabel "x, x'"
set title "time series: the last 8 forcing periods"
set xrange [516.2241959042722:600]
plot 'trajectory.tsv' using 't':'x' with lines lw 1.5 lc rgb '#0072b2' title "displacement x", \
     'trajectory.tsv' using 't':'xdot' with lines lw 1.5 lc rgb '#d55e00' title "velocity x'"
unset multiplot
set autoscale x
set bmargin 7
set terminal pngcairo size 950,750 enhanced font 'Sans,12'
set output "section.png"
set title "stroboscopic section (every forcing period)\n" . "cubic law: β = 0.05, v = 0.25, μ_s = 0.4, μ_m = 0.25, v_m = 0.5, A = 0.3, Ω = 0.6"
set xlabel "x"
set ylabel "x'"
set offsets graph 0.04, graph 0.04, graph 0.04, graph 0.04
plot 'section.tsv' using (column('x')):(column('t') < 300 ? column('xdot') : NaN) with points pt 6 ps 0.6 lc rgb '#b0b0b0' title "transient (t < 300)", \
     'section.tsv' using (column('x')):(column('t') >= 300 ? column('xdot') : NaN) with points pt 7 ps 0.8 lc rgb '#0072b2' title "after the transient (t ≥ 300)"
