# Bifurcation diagrams written by ss_continue; run `gnuplot bifurcation.gp` in this
# directory. Solid: stable, dashed: unstable; blue stick-slip, vermillion pure slip,
# gray steady sliding. GR grazing-sliding, HB Hopf, LP fold.
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
set xlabel "belt speed v (dimensionless)"
set title "Stribeck law: β = 0.05, μ_s = 0.4, μ_k = 0.25, v_s = 0.5"
set offsets 0, 0, graph 0.08, graph 0.08
set xrange [up*0.3:up*0.8]
set output 'bifurcation_x.png'.suffix
set ylabel "displacement x: min and max (dimensionless)"
set label 100 'HB' at up*0.5493061443340549,ul*0.3 center offset 0,1.1 boxed front font ',10' point ls 8
set label 101 'GR' at up*0.6519468583211344,ul*0.9689424675414187 center offset 0,1.1 boxed front font ',10' point ls 8
set label 102 'LP' at up*0.6519468583211344,ul*0.9689424675414187 center offset 0,-1.1 boxed front font ',10' point ls 8
plot 'branch.tsv' using ($1*up):((strcol(2) eq 'equilibrium' && $3==0 && $11==0) ? $6*ul : NaN) with lines ls 6 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'equilibrium' && $3==0 && $11==1) ? $6*ul : NaN) with lines ls 5 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'stick-slip' && $3==1 && $11==1) ? $6*ul : NaN) with lines ls 1 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'pure-slip' && $3==1 && $11==0) ? $6*ul : NaN) with lines ls 4 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'stick-slip' && $3==1 && $11==1) ? $5*ul : NaN) with lines ls 1 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'pure-slip' && $3==1 && $11==0) ? $5*ul : NaN) with lines ls 4 notitle, \
     NaN with lines ls 1 title 'stick-slip, stable', \
     NaN with lines ls 4 title 'pure slip, unstable', \
     NaN with lines ls 6 title 'steady sliding, unstable', \
     NaN with lines ls 5 title 'steady sliding, stable'
unset label
unset output
set output 'bifurcation_xdot.png'.suffix
set ylabel "velocity dx/dt: min and max (dimensionless)"
set label 100 'HB' at up*0.5493061443340549,uv*0 center offset 0,1.1 boxed front font ',10' point ls 8
set label 101 'GR' at up*0.6519468583211344,uv*0.6519468583211344 center offset 0,1.1 boxed front font ',10' point ls 8
set label 102 'LP' at up*0.6519468583211344,uv*0.6519468583211344 center offset 0,-1.1 boxed front font ',10' point ls 8
plot 'branch.tsv' using ($1*up):((strcol(2) eq 'equilibrium' && $3==0 && $11==0) ? $8*uv : NaN) with lines ls 6 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'equilibrium' && $3==0 && $11==1) ? $8*uv : NaN) with lines ls 5 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'stick-slip' && $3==1 && $11==1) ? $8*uv : NaN) with lines ls 1 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'pure-slip' && $3==1 && $11==0) ? $8*uv : NaN) with lines ls 4 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'stick-slip' && $3==1 && $11==1) ? $7*uv : NaN) with lines ls 1 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'pure-slip' && $3==1 && $11==0) ? $7*uv : NaN) with lines ls 4 notitle, \
     NaN with lines ls 1 title 'stick-slip, stable', \
     NaN with lines ls 4 title 'pure slip, unstable', \
     NaN with lines ls 6 title 'steady sliding, unstable', \
     NaN with lines ls 5 title 'steady sliding, stable'
unset label
unset output
set output 'period.png'.suffix
set ylabel "period T (dimensionless)"
set label 100 'HB' at up*0.5493061443340549,ut*6.283185307179586 center offset 0,1.1 boxed front font ',10' point ls 8
set label 101 'GR' at up*0.6519468583211344,ut*6.287235031161014 center offset 0,1.1 boxed front font ',10' point ls 8
set label 102 'LP' at up*0.6519468583211344,ut*6.287235031161014 center offset 0,-1.1 boxed front font ',10' point ls 8
plot 'branch.tsv' using ($1*up):((strcol(2) eq 'stick-slip' && $3==1 && $11==1) ? $4*ut : NaN) with lines ls 1 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'pure-slip' && $3==1 && $11==0) ? $4*ut : NaN) with lines ls 4 notitle, \
     NaN with lines ls 1 title 'stick-slip, stable', \
     NaN with lines ls 4 title 'pure slip, unstable'
unset label
unset output
set terminal pngcairo size 1000,1000 enhanced font 'Sans,12'
set output 'multiplier.png'.suffix
set multiplot layout 2,1 title "stability along the branch"
set lmargin 12
set title "periodic orbits: stable while the multiplier is below 1"
set ylabel "nontrivial Floquet multiplier"
set label 100 'GR' at up*0.6519468583211344,1*0 center offset 0,1.1 boxed front font ',10' point ls 8
set label 101 'LP' at up*0.6519468583211344,1*0 center offset 0,-1.1 boxed front font ',10' point ls 8
plot 'branch.tsv' using ($1*up):((strcol(2) eq 'stick-slip' && $3==1 && $11==1) ? $10*1 : NaN) with lines ls 1 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'pure-slip' && $3==1 && $11==0) ? $10*1 : NaN) with lines ls 4 notitle, \
     NaN with lines ls 1 title 'stick-slip, stable', \
     NaN with lines ls 4 title 'pure slip, unstable', \
     1 with lines ls 7 title 'threshold 1'
unset label
set title "steady sliding: stable while the largest Re λ is below 0"
set ylabel "largest real part of the eigenvalues, Re λ"
set label 100 'HB' at up*0.5493061443340549,1*0 center offset 0,1.1 boxed front font ',10' point ls 8
plot 'branch.tsv' using ($1*up):((strcol(2) eq 'equilibrium' && $3==0 && $11==0) ? $10*1 : NaN) with lines ls 6 notitle, \
     'branch.tsv' using ($1*up):((strcol(2) eq 'equilibrium' && $3==0 && $11==1) ? $10*1 : NaN) with lines ls 5 notitle, \
     NaN with lines ls 6 title 'steady sliding, unstable', \
     NaN with lines ls 5 title 'steady sliding, stable', \
     0 with lines ls 7 title 'threshold 0'
unset label
unset multiplot
unset output
