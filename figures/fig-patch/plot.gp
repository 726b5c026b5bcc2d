# The crack patch test: sigma_xx at the points of the upper half of the
# full DCB with an explicit crack (left; the crack in black on y = 0) and of
# the half DCB held in y on the ligament by symmetry (right; the held nodes
# dashed), static state, one colour scale; the measured difference below.
# Variables: full, half, label, out (set with gnuplot -e by make.sh).
set datafile separator ","
set terminal pngcairo size 1600,360 font ",12" noenhanced
set output out
stats half using 5 skip 2 nooutput
m = (abs(STATS_min) > abs(STATS_max)) ? abs(STATS_min) : abs(STATS_max)
set cbrange [-m:m]
set palette defined (-1 "#2040c0", 0 "#f0f0f0", 1 "#c02020")
set cblabel "sigma_xx (MPa)"
set format cb "%.4f"
set xrange [-3:104]
set yrange [-2:24]
set size ratio -1
set xlabel "x (mm)"
set ylabel "y (mm)"
set key off
top = "Crack patch test: the full DCB's upper half equals the half DCB by symmetry"
set multiplot layout 1,2 margins 0.05, 0.88, 0.16, 0.82 spacing 0.03 \
    title top."\n".label
set title "full DCB with an explicit crack (CRAMP, stage 2): y > 0"
unset colorbox                          # one colour scale: the right one
plot full using 1:($2 > 0 ? $2 : 1/0):5 skip 2 with points pt 5 ps 0.7 palette, \
     "+" using (-1.9607843137254901 + 51.9607843137254901 * $0 / 99):(0) every ::0::99 \
         with lines lw 3 lc "black"
set title "half DCB, ligament held in y (conventional MPM)"
set colorbox
unset ylabel
plot half using 1:2:5 skip 2 with points pt 5 ps 0.7 palette, \
     "+" using (50 + 50 * $0 / 99):(0) every ::0::99 with lines lw 3 dt 2 lc "black"
unset multiplot
