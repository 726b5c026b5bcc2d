# Fig. 2: sigma_xx along the mid-plane, CRAMP against FEA.
set datafile separator ","
set termoption noenhanced
set datafile missing "nan"
set terminal pngcairo size 900,600 font ",12"
set output out
set title "Fig. 2: sigma_xx along the mid-plane of the DCB (crack tip at x = 50 mm)"
set xlabel "distance along the mid-plane (mm)"
set ylabel "sigma_xx (MPa)"
set key top left
set grid
plot data using 1:3 skip 1 with lines lw 2 lc "black" title "static FEA, Q4 on the same grid", \
     data using 1:2 skip 1 with points pt 7 ps 1.1 lc "red" title "CRAMP (particle stresses extrapolated to the grid)"
