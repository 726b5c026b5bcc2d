# fig-shapes: (a) the flying bar's error against the cell size, (b) the
# spinning disk's spurious stress, (c) the DCB's opening error and (d) the
# beam impact's energy error (fig-tradeoff's measures) against the cost per
# particle-step.  Called by figures/fig-shapes/make.sh with bar, disk, dcb,
# beam (CSV: shape, instructions per particle-step, error), beamnote
# (the shapes left off (d), or empty) and out.
set terminal pngcairo size 1300,1120 font 'Sans,11'
set output out
set multiplot layout 2,2
set logscale xy
set grid
set format y '10^{%T}'

set title "(a) Bar flying at c/5 through the grid, first mode (1.25 periods)"
set xlabel 'cell size h (mm), bar 16 mm long'
set ylabel 'RMS displacement error / amplitude'
set xrange [0.02:3]
set yrange [1e-7:1e5]
set key bottom right
plot bar index 0 using 1:2 with linespoints lw 2 pt 7 title 'linear', \
     bar index 1 using 1:2 with linespoints lw 2 pt 5 title 'uGIMP', \
     bar index 2 using 1:2 with linespoints lw 2 pt 9 title 'CPDI', \
     bar index 3 using 1:2 with linespoints lw 2 dt 2 pt 6 title 'linear, bar at rest (no crossing)', \
     1e-4 * (x / 0.25)**2 with lines dt 3 lc rgb 'gray50' title 'h^2'

set title "(b) Spinning disk, one turn (MUSL unless marked)"
set datafile separator ','
set xlabel 'instructions per particle-step (callgrind)'
set ylabel 'largest von Mises stress / {/Symbol r} v^2 after the turn'
set xrange [700:30000]
set yrange [0.3:100]
set format y '%g'
set key bottom left
plot disk using 2:3 with points pt 7 ps 1.5 lc rgb 'black' notitle, \
     disk using 2:3:1 with labels offset char 0.8,0.6 left font ',9' notitle, \
     0.82 with lines dt 2 lc rgb 'gray50' title 'physics: 0.41 at the centre, a start rings to about twice'

set title "(c) fig-tradeoff's DCB at its front's knee: h = 2 mm, 2 x 2 points (400 ms)"
set ylabel '|opening / converged FEA - 1|'
set xrange [500:20000]
set yrange [0.01:0.1]
set ytics (0.01, 0.02, 0.03, 0.04, 0.05, 0.07, 0.1)
plot dcb using 2:3 with points pt 7 ps 1.5 lc rgb 'black' notitle, \
     dcb using 2:3:1 with labels offset char 0.8,0.6 left font ',10' notitle

set title "(d) fig-tradeoff's beam impact, musl, cfl 0.5 (to 2 ms, contact)"
set ylabel 'energy error, max |E/E0 - 1|'
set yrange [1e-4:1]
set ytics auto
set format y '10^{%T}'
if (strlen(beamnote) > 0) set label 1 beamnote at graph 0.03, graph 0.08 font ',10' noenhanced
plot beam using 2:3 with points pt 7 ps 1.5 lc rgb 'black' notitle, \
     beam using 2:3:1 with labels offset char 0.8,0.6 left font ',10' notitle
unset multiplot
