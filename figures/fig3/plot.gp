# The paper's Fig. 3: sigma_xx of the points of the two cracked disks at the
# four times of frames A-D, one colour scale for all, cracks in black.
# Variables (gnuplot -e): dir (snap_K.csv, cracks_K.csv), out, times.
set terminal pngcairo size 900,640 font ",10"
set termoption noenhanced
set output out
set datafile separator ","
set multiplot layout 2,2 title "Fig. 3: cracked disks colliding, frictionless crack contact (sigma_xx, MPa)"
m = 0
do for [k=0:3] {
    stats sprintf("%s/snap_%d.csv", dir, k) using 3 skip 2 nooutput
    m = (abs(STATS_min) > m) ? abs(STATS_min) : m
    m = (abs(STATS_max) > m) ? abs(STATS_max) : m
}
set cbrange [-m:m]
set palette defined (-1 "#2040c0", 0 "#f0f0f0", 1 "#c02020")
set size ratio -1
set xrange [-6:78]
set yrange [2:38]
set key off
set tics font ",8"
frame = "ABCD"
do for [k=0:3] {
    set title sprintf("%s: t = %.1f ms", frame[k+1:k+1], real(word(times, k+1)))
    plot sprintf("%s/snap_%d.csv", dir, k) using 1:2:3 skip 2 with points pt 5 ps 0.25 palette, \
         sprintf("%s/cracks_%d.csv", dir, k) using 1:2 with lines lw 2 lc "black"
}
unset multiplot
