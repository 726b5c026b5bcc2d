# Error against cost, log-log, each run labelled with its setting and the
# Pareto front drawn.  Called by figures/fig-tradeoff/make.sh with data and
# front (CSV: label, group, loop s, error), names (one per group), ylab,
# title and out.
set datafile separator ','
set terminal pngcairo size 1100,760 font 'Sans,11'
set output out
set termoption noenhanced
set logscale xy
set format y '%g'
set xlabel 'cost: wall time of the time loop (s)'
set ylabel ylab
set title title
set key top right box opaque
set grid
set offsets graph 0.02, graph 0.12, graph 0.08, graph 0.08
n = words(names)
plot front using 3:4 with lines lw 6 lc rgb '#c0c0c0' title 'Pareto front', \
     for [g = 1:n] data using 3:($2 == g ? $4 : NaN) with points pt 7 ps 1.3 lc g \
         title word(names, g), \
     for [g = 1:n] data using 3:($2 == g ? $4 : NaN):1 with labels left \
         offset char 0.6, 0.35 font ',9' tc lt g notitle
