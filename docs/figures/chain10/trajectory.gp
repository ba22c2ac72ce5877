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
set multiplot layout 1,2 title "chain: v = 0.3, kc = 0.5, β = 0.05, m1 = 1, c1 = 0.1, k1 = 1, mu\\_s1 = 0.4, m2 = 1, c2 = 0.1, k2 = 1,\nmu\\_s2 = 0.4, m3 = 1, c3 = 0.1, k3 = 1, mu\\_s3 = 0.4, m4 = 1, c4 = 0.1, k4 = 1, mu\\_s4 = 0.4, m5 = 1, c5 = 0.1,\nk5 = 1, mu\\_s5 = 0.4, m6 = 1, c6 = 0.1, k6 = 1, mu\\_s6 = 0.4, m7 = 1, c7 = 0.1, k7 = 1, mu\\_s7 = 0.4, m8 = 1,\nc8 = 0.1, k8 = 1, mu\\_s8 = 0.4, m9 = 1, c9 = 0.1, k9 = 1, mu\\_s9 = 0.4, m10 = 1, c10 = 0.1, k10 = 1,\nmu\\_s10 = 0.4"
set offsets 0, 0, graph 0.04, graph 0.04
set xlabel "x1"
set ylabel "x1'"
set title 'phase portrait'
plot 'trajectory.tsv' using (column('x1')):(column('t') < 150 ? column('x1dot') : NaN) with lines lw 1 lc rgb '#b0b0b0' title "transient (t < 150)", \
     'trajectory.tsv' using (column('x1')):(column('t') >= 150 ? column('x1dot') : NaN) with lines ls 1 lw 1.5 title "after the transient (t ≥ 150)", \
     'trajectory.tsv' using (column('x1')):(substr(strcol('mode'), 1, 5) eq 'stick' ? column('x1dot') : NaN) with lines ls 9 title "contact 1 sticking"
set offsets 0, 0, 0, 0
set xlabel 'time t'
set ylabel "displacements"
set title "time series: the last 50.3 time units"
set xrange [249.7345175425633:300]
plot 'trajectory.tsv' using 't':'x1' with lines lw 1.5 lc rgb '#0072b2' title "displacement x1", \
     'trajectory.tsv' using 't':'x2' with lines lw 1.5 lc rgb '#d55e00' title "displacement x2", \
     'trajectory.tsv' using 't':'x3' with lines lw 1.5 lc rgb '#009e73' title "displacement x3", \
     'trajectory.tsv' using 't':'x4' with lines lw 1.5 lc rgb '#cc79a7' title "displacement x4", \
     'trajectory.tsv' using 't':'x5' with lines lw 1.5 lc rgb '#e69f00' title "displacement x5", \
     'trajectory.tsv' using 't':'x6' with lines lw 1.5 lc rgb '#56b4e9' title "displacement x6", \
     'trajectory.tsv' using 't':'x7' with lines lw 1.5 lc rgb '#000000' title "displacement x7", \
     'trajectory.tsv' using 't':'x8' with lines lw 1.5 lc rgb '#f0e442' title "displacement x8", \
     'trajectory.tsv' using 't':'x9' with lines lw 1.5 lc rgb '#0072b2' title "displacement x9", \
     'trajectory.tsv' using 't':'x10' with lines lw 1.5 lc rgb '#d55e00' title "displacement x10"
unset multiplot
set autoscale x
set bmargin 7
set terminal pngcairo size 950,750 enhanced font 'Sans,12'
set output "section.png"
set title "exit map (stick exits)\n" . "chain: v = 0.3, kc = 0.5, β = 0.05, m1 = 1, c1 = 0.1, k1 = 1, mu\\_s1 = 0.4, m2 = 1, c2 = 0.1, k2 = 1,\nmu\\_s2 = 0.4, m3 = 1, c3 = 0.1, k3 = 1, mu\\_s3 = 0.4, m4 = 1, c4 = 0.1, k4 = 1, mu\\_s4 = 0.4, m5 = 1, c5 = 0.1,\nk5 = 1, mu\\_s5 = 0.4, m6 = 1, c6 = 0.1, k6 = 1, mu\\_s6 = 0.4, m7 = 1, c7 = 0.1, k7 = 1, mu\\_s7 = 0.4, m8 = 1,\nc8 = 0.1, k8 = 1, mu\\_s8 = 0.4, m9 = 1, c9 = 0.1, k9 = 1, mu\\_s9 = 0.4, m10 = 1, c10 = 0.1, k10 = 1,\nmu\\_s10 = 0.4"
set xlabel "x1 at stick exit n"
set ylabel "x1 at stick exit n+1"
set size square
prev = NaN
plot x with lines lc rgb '#aaaaaa' dt 2 notitle, \
     'section.tsv' using (q = prev, prev = column('x1'), q):(column('t') < 150 ? column('x1') : NaN) with points pt 6 ps 0.6 lc rgb '#b0b0b0' title "transient (t < 150)", \
     prev = NaN, 'section.tsv' using (q = prev, prev = column('x1'), q):(column('t') >= 150 ? column('x1') : NaN) with points pt 7 ps 0.8 lc rgb '#0072b2' title "after the transient (t ≥ 150)"
