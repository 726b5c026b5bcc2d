# Error against cost, log-log, each run labelled with its setting and the
# Pareto front drawn.  Called by figures/fig-tradeoff/make.sh with data and
# front (CSV: label, group, loop s, error), names (one per group), ylab,
# title and out; note (optional) is written under the title.  Errors above
# ycap (default 1) are drawn at ycap as triangles, labelled downwards with
# their value.  Rows alternate: even rows labelled right of and above their
# points, odd rows left and below, so that neighbours overlap less.
set datafile separator ','
set terminal pngcairo size 1500,950 font 'Sans,11'
set output out
set termoption noenhanced
if (!exists("ycap")) ycap = 1
cap(y) = y > ycap ? ycap : y
set logscale xy
set format y '%g'
set autoscale fix
set offsets graph 0.08, graph 0.08, graph 0.1, graph 0.06
set xlabel 'cost: wall time of the time loop (s)'
set ylabel ylab
set title title
set key bottom left box opaque
set grid
n = words(names)
if (exists("note")) set label 1 note at graph 0.5, graph 0.97 center font ',10'
row(g, k) = (column(2) == g && int(column(0)) % 2 == k && column(4) <= ycap) ? column(4) : NaN
plot front using 3:(cap($4)) with lines lw 6 lc rgb '#c0c0c0' title 'Pareto front', \
     for [g = 1:n] data using 3:($2 == g && $4 <= ycap ? $4 : NaN) with points pt 7 ps 1.3 lc g \
         title word(names, g), \
     for [g = 1:n] data using 3:($2 == g && $4 > ycap ? ycap : NaN) with points pt 9 ps 2 lc g \
         notitle, \
     for [g = 1:n] data using 3:(row(g, 0)):1 with labels left offset char 0.7, 0.45 \
         font ',9' tc lt g notitle, \
     for [g = 1:n] data using 3:(row(g, 1)):1 with labels right offset char -0.7, -0.45 \
         font ',9' tc lt g notitle, \
     for [g = 1:n] data using 3:($2 == g && $4 > ycap ? ycap : NaN): \
         (stringcolumn(1) . sprintf(': %.3g', $4)) with labels rotate by -90 left \
         offset char 0, -1.2 font ',9' tc lt g notitle
