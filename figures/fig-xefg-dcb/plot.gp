# CRAMP against XEFG on the DCB: error against cost, log-log, two panels
# (the crack-mouth opening, the energy release rate G), one curve per
# series (a method at a load), each point labelled with its cell size h and
# signed error.  Called by figures/fig-xefg-dcb/make.sh with data (CSV: the
# opening's label, G's label, loop s, |opening error|, |G error|; one block
# per series, two blank lines apart), series
# (their names in the blocks' order) and out.
set datafile separator ','
set terminal pngcairo size 1600,720 font 'Sans,11'
set output out
set termoption noenhanced
n = words(series)
# 'mpm', 'xefg', 'mpm:0.1' (the load in mN after the colon): the key's names
load(w) = strstrt(w, ':') ? ' at ' . w[strstrt(w, ':') + 1:] . ' mN' : ' at 1 mN'
name(w) = strstrt(w, ':') ? w[1:strstrt(w, ':') - 1] : w
title(w) = (name(w) eq 'mpm' ? 'CRAMP (mpm, musl)' : (name(w) eq 'xefg' ? 'XEFG (default settings)' : name(w))) . load(w)
dash(w) = strstrt(w, ':') ? 2 : 1              # another load: dashed,
colour(w) = name(w) eq 'xefg' ? 2 : 1           # the method's colour,
up(w) = name(w) eq 'mpm' && !strstrt(w, ':') ? 0.6 : -0.7   # labels above
                                                # CRAMP at 1 mN, below the others
set logscale xy
set format y '%g'
set ytics add (0.1, 0.2, 0.3, 0.5, 0.7, 1, 1.5, 2, 3, 4, 5, 7, 10)
set autoscale fix
set offsets graph 0.06, graph 0.3, graph 0.15, graph 0.15
set xlabel 'cost: wall time of the time loop of one run (s); G takes three runs'
set key bottom left box opaque
set grid
set multiplot layout 1, 2 title \
    'DCB (figures/fig1/dcb_full.cfg, 2 x 2 points per cell, static): error from the converged Q4 FEA against cost' \
    font ',13'
set title 'crack-mouth opening at the load'
set ylabel '|opening / FEA - 1| (%)'
plot for [g = 1:n] data index g - 1 using 3:(100 * $4) with linespoints lw 2 pt 7 ps 1.4 \
         dt dash(word(series, g)) lc colour(word(series, g)) title title(word(series, g)), \
     for [g = 1:n] data index g - 1 using 3:(100 * $4):1 with labels left \
         offset char 0.8, up(word(series, g)) font ',10' tc lt colour(word(series, g)) notitle
set title 'energy release rate G = P^2/(2B) dC/da, central difference over a0 -/+ dx'
set ylabel '|G / G FEA - 1| (%)'
plot for [g = 1:n] data index g - 1 using 3:(100 * $5) with linespoints lw 2 pt 7 ps 1.4 \
         dt dash(word(series, g)) lc colour(word(series, g)) title title(word(series, g)), \
     for [g = 1:n] data index g - 1 using 3:(100 * $5):2 with labels left \
         offset char 0.8, up(word(series, g)) font ',10' tc lt colour(word(series, g)) notitle
unset multiplot
