# Error against cost, log-log, each run labelled with its setting and the
# Pareto front drawn.  Called by figures/fig-tradeoff/make.sh with
# data (CSV: label, group, loop s, error, side of the label: 0 right above,
# 1 right below, 2 left above, 3 left below), front (the first four),
# names (one per group), ylab, title and out; note (optional) is written
# under the title.  Errors above ycap (default 1) are drawn at ycap as
# triangles, labelled downwards with their value.
set datafile separator ','
set terminal pngcairo size 1500,950 font 'Sans,11'
set output out
set termoption noenhanced
if (!exists("ycap")) ycap = 1
cap(y) = y > ycap ? ycap : y
set logscale xy
set format y '%g'
set ytics add (0.0002, 0.0005, 0.002, 0.005, 0.02, 0.05, 0.2, 0.5, 2, 5, 20, 50)
set autoscale fix
set offsets graph 0.08, graph 0.08, graph 0.1, graph 0.06
set xlabel 'cost: wall time of the time loop (s)'
set ylabel ylab
set title title
set key bottom left box opaque
set grid
n = words(names)
if (exists("note")) set label 1 note at graph 0.5, graph 0.97 center font ',10'
side(g, q) = (column(2) == g && column(5) == q && column(4) <= ycap) ? column(4) : NaN
plot front using 3:(cap($4)) with lines lw 6 lc rgb '#c0c0c0' title 'Pareto front', \
     for [g = 1:n] data using 3:($2 == g && $4 <= ycap ? $4 : NaN) with points pt 7 ps 1.3 lc g \
         title word(names, g), \
     for [g = 1:n] data using 3:($2 == g && $4 > ycap ? ycap : NaN) with points pt 9 ps 2 lc g \
         notitle, \
     for [g = 1:n] for [q = 0:1] data using 3:(side(g, q)):1 with labels left \
         offset char 0.7, (q ? -0.5 : 0.5) font ',9' tc lt g notitle, \
     for [g = 1:n] for [q = 2:3] data using 3:(side(g, q)):1 with labels right \
         offset char -0.7, (q == 3 ? -0.5 : 0.5) font ',9' tc lt g notitle, \
     for [g = 1:n] data using 3:($2 == g && $4 > ycap ? ycap : NaN): \
         (stringcolumn(1) . sprintf(': %.3g', $4)) with labels rotate by -90 left \
         offset char 0, -1.2 font ',9' tc lt g notitle
