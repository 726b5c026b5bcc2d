# Issue 7: sigma_xx along the ligament against the distance from the crack
# tip in the static state (the tip moves about 0.25 mm left of x = 50),
# tip on a node and mid-cell, on three grids, with the converged FEA.
# Filled symbols: the MPM's nodal values; open symbols: the FEA sampled as
# the MPM samples (its stresses at the points' initial positions,
# extrapolated with the weights of their final positions) on the same grid.
set datafile separator ","
set datafile missing "nan"
set terminal pngcairo size 1500,520 font ",11" noenhanced
set output out
set multiplot layout 1,3 title "DCB, 2 mN: sigma_xx on the ligament, crack tip on a node (red) and mid-cell (blue)"
set xrange [0:21]
set yrange [0:0.0045]
set xlabel "distance from the static crack tip (mm)"
set ylabel "sigma_xx (MPa)"
set grid
set key top right
fea = dir.'/tip_node_05mm.csv'
node(n) = dir.'/tip_node_'.n.'.csv'
mid(n) = dir.'/tip_mid_'.n.'.csv'
array cells[3] = ["2 mm cells (mid-cell: 100/51)", "1 mm cells (mid-cell: 100/101)", \
                  "0.5 mm cells (mid-cell: 100/201)"]
do for [k = 1:3] {
    n = word("2mm 1mm 05mm", k)
    m = word("51 101 201", k)
    set title cells[k]
    plot fea using 2:5 skip 1 with lines lw 2 lc "black" title "converged FEA", \
         node(n) using 2:3 skip 1 with linespoints pt 7 ps 1.0 lc "red" title "MPM, tip on a node", \
         node(n) using 2:7 skip 1 with points pt 6 ps 1.3 lc "red" title "FEA sampled as the MPM", \
         mid(m) using 2:3 skip 1 with linespoints pt 5 ps 1.0 lc "blue" title "MPM, tip mid-cell", \
         mid(m) using 2:7 skip 1 with points pt 4 ps 1.3 lc "blue" title "FEA sampled as the MPM"
}
unset multiplot
