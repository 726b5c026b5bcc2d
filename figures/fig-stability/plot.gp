# The stability map of figures/fig-stability/make.sh: one panel per scheme,
# x the cfl factor, y the points per cell, each cell coloured by what the
# run did, with the stop time or the energy error written in it. Called
# with: data (blocks per scheme: panel, column, cfl, ppc, code, label,
# second label), out, schemes, cfls, ppcs, bound, tend.
set terminal pngcairo size 1600,1000 font 'Sans,11' noenhanced
set output out

ncol = words(cfls)
nrow = words(ppcs)
colour(code) = code == 0 ? 0x2ca02c : code == 1 ? 0xff9f1c : code == 2 ? 0xd62728 : 0xa0a0a0
set xrange [0.5:ncol + 0.5]
set yrange [0.5:nrow + 0.5]
set xtics () scale 0
set ytics () scale 0
set for [i = 1:ncol] xtics add (word(cfls, i) i)
set for [j = 1:nrow] ytics add (sprintf('%sx%s', word(ppcs, j), word(ppcs, j)) j)
set xlabel 'cfl factor (dt = cfl x cell / wave speed)' offset 0,0.3
set key spacing 1.0 height 0.5
set ylabel 'points per cell'
set key below horizontal samplen 1.5 font ',10'
set style fill solid 1.0 border lc rgb 'white'

set multiplot layout 2,2 title sprintf("Beam impact with contact between bodies (figures/fig6/beam_supports.cfg), run to %s ms.\n\
stable: max |E/E0 - 1| <= %g %% (written in the cell); drifting: above it; stopped: unstable, stopped with the step and the point and quantity, or the energy past twice its start (its time in ms written).\n\
cfl > 1 is refused at input; below 'refused': the same run with allow_cfl_above_one = true.", tend, 100 * bound) \
    font ',11'
# the row of a ppc value
row(n) = sum [j = 1:nrow] (word(ppcs, j) + 0 == n ? j : 0)
do for [k = 1:words(schemes)] {
    s = word(schemes, k)
    set title (s eq 'usl' ? 'USL' : s eq 'musl' ? 'MUSL' : s eq 'usf' ? 'USF' : s eq 'usavg' ? 'USAVG' : s) font ',13'
    plot data index (k - 1) using 2:(row($4)):(0.5):(0.5):(colour($5)) \
             with boxxyerror lc rgb variable notitle, \
         '' index (k - 1) using 2:(row($4) + ($5 == 3 ? 0.17 : 0)):6 with labels font ',9' notitle, \
         '' index (k - 1) using 2:(row($4) - 0.17):($5 == 3 ? stringcolumn(7) : '') \
             with labels font ',8' notitle, \
         keyentry with boxes lc rgb '#2ca02c' title 'stable', \
         keyentry with boxes lc rgb '#ff9f1c' title 'drifting', \
         keyentry with boxes lc rgb '#d62728' title 'stopped', \
         keyentry with boxes lc rgb '#a0a0a0' title 'refused'
}
unset multiplot
