# Opening of the two cracks of Fig. 3 against time (the mean gap of the
# faces' points less its start value), with the nodes in contact.
# Variables (gnuplot -e): dir (openings.csv), out.
set terminal pngcairo size 900,420 font ",10"
set termoption noenhanced
set output out
set datafile separator ","
set xlabel "time (ms)"
set ylabel "crack opening (mm)"
set y2label "nodes in contact"
set ytics nomirror
set y2tics
set key top right
set title "Fig. 3: openings of the two cracks (frictionless contact)"
plot dir."/openings.csv" using 1:2 skip 1 with lines lw 2 lc "#c02020" title "left crack (along the impact axis)", \
     dir."/openings.csv" using 1:3 skip 1 with lines lw 2 lc "#2040c0" title "right crack (across it)", \
     dir."/openings.csv" using 1:4 skip 1 axes x1y2 with lines lw 1 lc "#909090" title "nodes in contact"
