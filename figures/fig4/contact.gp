# Fig. 4's crack contact against time: the nodes where the crack's faces
# are in contact (detected and adjusted), the nodes in contact between
# bodies, and the crack's opening (mean gap of its faces' points less its
# start value).  Contact before the wave enters the cracked disk is the
# grey zone's approach test (eq. 12) taking the sign of round-off-sized
# velocities there; it moves nothing.
# Variables (gnuplot -e): dir (contact.csv), out, t (the figure's time), t0
# (first contact between bodies), t3 (first dark fringe in the cracked disk).
set terminal pngcairo size 1000,640 font ",10"
set termoption noenhanced
set output out
set datafile separator ","
set multiplot layout 2,1 title "Fig. 4: crack-face contact as the waves pass the cracked disk (frictionless)"
set xrange [0.035:0.1]
set lmargin 10
set rmargin 10
set key bottom right
set ylabel "nodes in contact"
set arrow 1 from t0, graph 0 to t0, graph 1 nohead dt 2 lc rgb "#808080"
set arrow 2 from t3, graph 0 to t3, graph 1 nohead dt 2 lc rgb "#808080"
set arrow 3 from t, graph 0 to t, graph 1 nohead dt 2 lc rgb "#202020"
set label 1 "impactor meets disk 1" at t0, graph 0.03 left rotate by 90 offset -0.6,0 font ",8"
set label 2 "wave in the cracked disk" at t3, graph 0.03 left rotate by 90 offset -0.6,0 font ",8"
set label 3 "figure: front at the last disk" at t, graph 0.03 left rotate by 90 offset -0.6,0 font ",8"
set y2tics
set ytics nomirror
set y2label "nodes in contact between bodies"
set yrange [0:17]
set y2range [0:70]
plot dir."/contact.csv" using 1:2 skip 1 with steps lw 2 lc rgb "#c02020" title "crack faces", \
     dir."/contact.csv" using 1:3 skip 1 axes x1y2 with steps lw 1 lc rgb "#2040c0" title "between bodies (right axis)"
unset y2tics
unset y2label
unset label
set yrange [*:*]
set xlabel "time (ms)"
set ylabel "crack opening (um)"
set key top left
plot dir."/contact.csv" using 1:(1e3 * $4) skip 1 with lines lw 2 lc rgb "#202020" title "opening of the crack"
unset multiplot
