# CRAMP against XEFG on the DCB: error against cost, log-log, two panels
# (the crack-mouth opening, the energy release rate G), one curve per
# method, each point labelled with its cell size h and signed error.
# Called by figures/fig-xefg-dcb/make.sh with data (CSV: the opening's
# label, G's label, loop s, |opening error|, |G error|; one block per
# method, two blank lines apart), methods
# (their names in the blocks' order) and out.
set datafile separator ','
set terminal pngcairo size 1600,720 font 'Sans,11'
set output out
set termoption noenhanced
n = words(methods)
title(w) = w eq 'mpm' ? 'CRAMP (mpm, musl)' : (w eq 'xefg' ? 'XEFG (default settings)' : w)
set logscale xy
set format y '%g'
set ytics add (0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10)
set autoscale fix
set offsets graph 0.1, graph 0.12, graph 0.15, graph 0.15
set xlabel 'cost: wall time of the time loop of one run (s); G takes three runs'
set key top right box opaque
set grid
set multiplot layout 1, 2 title \
    'DCB (figures/fig1/dcb_full.cfg, 2 x 2 points per cell, static): error from the converged Q4 FEA against cost' \
    font ',13'
set title 'crack-mouth opening at the load'
set ylabel '|opening / FEA - 1| (%)'
plot for [g = 1:n] data index g - 1 using 3:(100 * $4) with linespoints lw 2 pt 7 ps 1.4 \
         lc g title title(word(methods, g)), \
     for [g = 1:n] data index g - 1 using 3:(100 * $4):1 with labels left \
         offset char 0.8, 0.6 font ',10' tc lt g notitle
set title 'energy release rate G = P^2/(2B) dC/da, central difference over a0 -/+ dx'
set ylabel '|G / G FEA - 1| (%)'
plot for [g = 1:n] data index g - 1 using 3:(100 * $5) with linespoints lw 2 pt 7 ps 1.4 \
         lc g title title(word(methods, g)), \
     for [g = 1:n] data index g - 1 using 3:(100 * $5):2 with labels left \
         offset char 0.8, 0.6 font ',10' tc lt g notitle
unset multiplot
