# Task 1's cost by crossing search against the number of points, for a crack
# of fixed length. Called by figures/fig-crossing/make.sh with data (one
# block per search: plain, screened, indexed) and out.
set datafile separator ','
set terminal pngcairo size 900,560 font 'Sans,11'
set output out
set logscale xy
set xrange [2500:90000]
set xlabel 'material points (DCB, crack 50 mm, grid refined twice)'
set ylabel 'Task 1, instructions per particle-step'
set title 'The crossing step by search (callgrind)'
set key bottom left
set grid
plot data index 0 using 1:4 with linespoints lw 2 pt 7 title 'plain: every segment', \
     data index 1 using 1:4 with linespoints lw 2 pt 5 title 'screened: crack extents (subtask 1)', \
     data index 2 using 1:4 with linespoints lw 2 pt 9 title 'indexed: segments by cell'

