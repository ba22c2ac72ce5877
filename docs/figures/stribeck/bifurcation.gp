# Bifurcation diagrams written by ss_continue; run `gnuplot bifurcation.gp` in this directory.
# Solid: stable, dashed: unstable, gray: steady sliding. GR grazing-sliding, HB Hopf,
# LP fold.
if (!exists('suffix')) suffix = ''
set terminal pngcairo size 1000,700 enhanced font ',12'
set datafile separator '\t'
set datafile columnheaders
set key top right
set grid
set xlabel 'v'
set title 'law=stribeck beta=0.05 v=[0.3, 0.8] mu_s=0.4 mu_k=0.25 v_s=0.5' noenhanced
set output 'bifurcation_x.png'.suffix
set ylabel "x range (min and max)"
plot 'branch.tsv' using 1:(($3==0 && $11==1) ? $6 : NaN) with lines lc rgb 'gray50' lw 2 dt 1 notitle, \
     'branch.tsv' using 1:(($3==0 && $11==0) ? $6 : NaN) with lines lc rgb 'gray50' lw 2 dt 2 notitle, \
     'branch.tsv' using 1:(($3==1 && $11==1) ? $6 : NaN) with lines lc 1 lw 2 dt 1 title "x max", \
     'branch.tsv' using 1:(($3==1 && $11==0) ? $6 : NaN) with lines lc 1 lw 2 dt 2 notitle, \
     'branch.tsv' using 1:(($3==1 && $11==1) ? $5 : NaN) with lines lc 3 lw 2 dt 1 title "x min", \
     'branch.tsv' using 1:(($3==1 && $11==0) ? $5 : NaN) with lines lc 3 lw 2 dt 2 notitle, \
     'special_points.tsv' using 2:5 with points pt 7 ps 1.2 lc rgb 'black' notitle, \
     'special_points.tsv' using 2:5:(strcol(1) eq 'LP' ? '' : strcol(1)) with labels offset 0,1.2 font ',11' notitle, \
     'special_points.tsv' using 2:5:(strcol(1) eq 'LP' ? 'LP' : '') with labels offset 0,-1.2 font ',11' notitle, \
     'special_points.tsv' using 2:4 with points pt 7 ps 1.2 lc rgb 'black' notitle, \
     'special_points.tsv' using 2:4:(strcol(1) eq 'LP' ? '' : strcol(1)) with labels offset 0,1.2 font ',11' notitle, \
     'special_points.tsv' using 2:4:(strcol(1) eq 'LP' ? 'LP' : '') with labels offset 0,-1.2 font ',11' notitle
unset output
set output 'bifurcation_xdot.png'.suffix
set ylabel "x' range (min and max)"
plot 'branch.tsv' using 1:(($3==0 && $11==1) ? $8 : NaN) with lines lc rgb 'gray50' lw 2 dt 1 notitle, \
     'branch.tsv' using 1:(($3==0 && $11==0) ? $8 : NaN) with lines lc rgb 'gray50' lw 2 dt 2 notitle, \
     'branch.tsv' using 1:(($3==1 && $11==1) ? $8 : NaN) with lines lc 1 lw 2 dt 1 title "x' max", \
     'branch.tsv' using 1:(($3==1 && $11==0) ? $8 : NaN) with lines lc 1 lw 2 dt 2 notitle, \
     'branch.tsv' using 1:(($3==1 && $11==1) ? $7 : NaN) with lines lc 3 lw 2 dt 1 title "x' min", \
     'branch.tsv' using 1:(($3==1 && $11==0) ? $7 : NaN) with lines lc 3 lw 2 dt 2 notitle, \
     'special_points.tsv' using 2:6 with points pt 7 ps 1.2 lc rgb 'black' notitle, \
     'special_points.tsv' using 2:6:(strcol(1) eq 'LP' ? '' : strcol(1)) with labels offset 0,1.2 font ',11' notitle, \
     'special_points.tsv' using 2:6:(strcol(1) eq 'LP' ? 'LP' : '') with labels offset 0,-1.2 font ',11' notitle
unset output
set output 'period.png'.suffix
set ylabel "period"
plot 'branch.tsv' using 1:(($3==0 && $11==1) ? $4 : NaN) with lines lc rgb 'gray50' lw 2 dt 1 notitle, \
     'branch.tsv' using 1:(($3==0 && $11==0) ? $4 : NaN) with lines lc rgb 'gray50' lw 2 dt 2 notitle, \
     'branch.tsv' using 1:(($3==1 && $11==1) ? $4 : NaN) with lines lc 1 lw 2 dt 1 title "period", \
     'branch.tsv' using 1:(($3==1 && $11==0) ? $4 : NaN) with lines lc 1 lw 2 dt 2 notitle, \
     'special_points.tsv' using 2:3 with points pt 7 ps 1.2 lc rgb 'black' notitle, \
     'special_points.tsv' using 2:3:(strcol(1) eq 'LP' ? '' : strcol(1)) with labels offset 0,1.2 font ',11' notitle, \
     'special_points.tsv' using 2:3:(strcol(1) eq 'LP' ? 'LP' : '') with labels offset 0,-1.2 font ',11' notitle
unset output
set output 'multiplier.png'.suffix
set ylabel "nontrivial Floquet multiplier (equilibrium: max Re lambda)"
plot 'branch.tsv' using 1:(($3==0 && $11==1) ? $10 : NaN) with lines lc rgb 'gray50' lw 2 dt 1 notitle, \
     'branch.tsv' using 1:(($3==0 && $11==0) ? $10 : NaN) with lines lc rgb 'gray50' lw 2 dt 2 notitle, \
     'branch.tsv' using 1:(($3==1 && $11==1) ? $10 : NaN) with lines lc 1 lw 2 dt 1 title "multiplier", \
     'branch.tsv' using 1:(($3==1 && $11==0) ? $10 : NaN) with lines lc 1 lw 2 dt 2 notitle
unset output
