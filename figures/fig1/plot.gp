# sigma_xx of the material points in colour, blue compression to red
# tension, with the crack drawn in black.  Variables: points, crack, out,
# title (set with gnuplot -e).
set datafile separator ","
set terminal pngcairo size 1200,560 font ",12" noenhanced
set output out
set title title
set size ratio -1
set xlabel "x (mm)"
set ylabel "y (mm)"
set cblabel "sigma_xx (MPa)"
stats points using 5 nooutput
m = (abs(STATS_min) > abs(STATS_max)) ? abs(STATS_min) : abs(STATS_max)
set cbrange [-m:m]
set palette defined (-1 "#2040c0", 0 "#f0f0f0", 1 "#c02020")
set key off
plot points using 1:2:5 skip 2 with points pt 5 ps 0.55 palette, \
     crack using 3:4 skip 2 with lines lw 3 lc "black"
