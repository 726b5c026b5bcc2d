# Issue 28: |K_I error| of the edge crack against the cell (spacing) h,
# log-log, for a/W = 0.3, 0.45, 0.6: CRAMP on its 2 mm and 1 mm domains,
# XEFG on its ring, with the issue's 3 % and a first-order slope.
# Variables: data (make.sh's table.dat: a/W W/h h CRAMP_F x3 err x3
# XEFG_F XEFG_err handbook), out, sigma (CRAMP's tension, MPa); set with
# gnuplot -e.
set terminal pngcairo size 1200,680 font ",12" noenhanced
set output out
set title "Edge crack in tension (W x H = 10 x 20 mm, plane strain): |K_I error| against Brown-Srawley\nCRAMP (tip mid-cell, sigma = ".sigma." MPa, domains of 1 and 2 mm) and XEFG (LEFM tip, ring 1.5-3 mm)"
set xlabel "cell size / point spacing h (mm), W = 10 mm"
set ylabel "|K_I / K_I(handbook) - 1| (%)"
set logscale xy
set xrange [0.1:0.6]
set yrange [0.0005:20]
set xtics ("W/20 = 0.5" 0.5, "W/40 = 0.25" 0.25, "W/80 = 0.125" 0.125)
set format y "%g"
set grid front
set key outside right top spacing 1.1 font ",10"
sel(r, c) = abs(column(1) - r) < 1e-6 ? abs(column(c)) : 1/0
plot 3 with lines lw 2 dt 2 lc "black" title "issue 28's bound, 3 %", \
     0.5 with lines lw 1 dt 3 lc "gray50" title "the handbook's own accuracy, 0.5 %", \
     12 * x with lines lw 1 dt 4 lc "gray30" title "first order (slope 1)", \
     data using 3:(sel(0.3, 9)) with linespoints pt 7 lw 2 lc "blue" title "CRAMP a/W = 0.3, 2 mm", \
     data using 3:(sel(0.45, 9)) with linespoints pt 7 lw 2 lc "red" title "CRAMP a/W = 0.45, 2 mm", \
     data using 3:(sel(0.6, 9)) with linespoints pt 7 lw 2 lc "dark-green" title "CRAMP a/W = 0.6, 2 mm", \
     data using 3:(sel(0.3, 7)) with linespoints pt 6 lw 1 lc "blue" title "CRAMP a/W = 0.3, 1 mm", \
     data using 3:(sel(0.45, 7)) with linespoints pt 6 lw 1 lc "red" title "CRAMP a/W = 0.45, 1 mm", \
     data using 3:(sel(0.6, 7)) with linespoints pt 6 lw 1 lc "dark-green" title "CRAMP a/W = 0.6, 1 mm", \
     data using 3:(sel(0.3, 11)) with linespoints pt 5 dt 2 lw 2 lc "blue" title "XEFG a/W = 0.3", \
     data using 3:(sel(0.45, 11)) with linespoints pt 5 dt 2 lw 2 lc "red" title "XEFG a/W = 0.45", \
     data using 3:(sel(0.6, 11)) with linespoints pt 5 dt 2 lw 2 lc "dark-green" title "XEFG a/W = 0.6"
