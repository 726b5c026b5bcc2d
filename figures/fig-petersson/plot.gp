# Petersson's beam: load against mid-span deflection (make.sh's curves:
# deflection mm, load N, ...), three point spacings and linear softening,
# with the two points of Petersson's measured curve that code_aster's
# ssnp166a checks.  Variables d1 d2 d3 (h = 20, 13.3, 10), dl (linear,
# h = 20), g1 g3 (grown from the notch, at the first and the last of
# GROW_SPACINGS, h1 and h3 mm), out, set with gnuplot -e.
set terminal pngcairo size 900,600 font ",12" noenhanced
set output out
set title "Petersson's notched beam (span 2000, D = 200, b = 50, a0 = 100 mm):\nXEFG with a cohesive ligament (pre-inserted, or grown from the notch), load against mid-span deflection"
set xlabel "mid-span deflection (mm)"
set ylabel "load P (N)"
set xrange [0:1.6]
set yrange [0:1100]
set grid
set key at graph 0.98, graph 0.98 right
$ref << EOD
0.365 774
0.607 598
EOD
plot d1 using 1:2 with lines lw 1.5 lc "orange" title "exponential, h = 20 mm", \
     d2 using 1:2 with lines lw 1.5 lc "forest-green" title "exponential, h = 13.3 mm", \
     d3 using 1:2 with lines lw 2 lc "blue" title "exponential, h = 10 mm", \
     dl using 1:2 with lines lw 1 dt 2 lc "gray40" title "linear softening, h = 20 mm", \
     g1 using 1:2 with lines lw 1 dt 3 lc "dark-red" title "grown from the notch, h = ".h1." mm", \
     g3 using 1:2 with lines lw 1.5 dt 4 lc "purple" title "grown from the notch, h = ".h3." mm", \
     $ref using 1:2:($2 * 0.1) with yerrorbars pt 7 ps 1.6 lc "red" title "Petersson (1981) as ssnp166a checks it, +-10 %"
