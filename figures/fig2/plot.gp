# Fig. 2: sigma_xx along the mid-plane, CRAMP against FEA.  Variables:
# data, out, tip (the crack tip's x, mm; set with gnuplot -e).
set datafile separator ","
set datafile missing "nan"
set terminal pngcairo size 900,600 font ",12" noenhanced
set output out
set title sprintf("Fig. 2: sigma_xx along the mid-plane of the DCB (crack tip at x = %g mm)", tip)
set xlabel "distance along the mid-plane (mm)"
set ylabel "sigma_xx (MPa)"
# headroom above the peak, and the key in the empty upper right
set yrange [0:*]
set offsets 0, 0, graph 0.25, 0
set key top right spacing 1.3
set grid
set arrow from tip, graph 0 to tip, graph 1 nohead dt 2 lw 1.5 lc "gray30"
set label "crack tip" at tip, graph 0.96 right offset -0.5, 0 tc "gray30"
plot data using 1:3 skip 1 with lines lw 2 lc "black" title "static FEA (Q4, same grid)", \
     data using 1:2 skip 1 with points pt 7 ps 1.1 lc "red" title "CRAMP (points to grid)"
