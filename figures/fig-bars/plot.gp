# make fig-bars: the bars' rebound error and energy change against the cell.
# Called by figures/fig-bars/make.sh with dat (rows: N scheme cfl rebound
# one-field chain dur energy), out and schemes.
set terminal pngcairo size 1200,480 font ",11"
set output out
set multiplot layout 1,2 title "Two identical bars colliding from a gap (scene\\_bars' study of the cell, cfl 0.25)"
set logscale xy
set xrange [15:400]
set xlabel "cells a bar, N"
set ylabel "rebound error against the exact v' (% of v0)"
set grid
set key top right
n = words(schemes)
plot for [i=1:n] dat using (strcol(2) eq word(schemes, i) ? $1 : 1/0):4 with linespoints lw 2 title word(schemes, i), \
     for [i=1:1] dat using (strcol(2) eq word(schemes, 1) ? $1 : 1/0):5 with lines dt 2 lc "gray40" title word(schemes, 1)." as one field", \
     dat using (strcol(2) eq word(schemes, 1) ? $1 : 1/0):6 with linespoints dt 3 lc "black" pt 6 title "lumped-mass chain, perfect wall", \
     2 with lines lc "red" dt 4 title "the issue's 2 %"
unset logscale y
set ylabel "energy change, end against start (%)"
set key bottom right
plot for [i=1:n] dat using (strcol(2) eq word(schemes, i) ? $1 : 1/0):8 with linespoints lw 2 title word(schemes, i), \
     0 with lines lc "black" dt 2 notitle
unset multiplot
