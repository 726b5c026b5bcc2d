# xefg.md Test 3: K_I / (sigma sqrt(pi a)) of the LEFM edge crack (a/W =
# 0.45) against the point spacing h, with the handbook F(0.45) and its 3 %
# band.  Variables: data (the table of make.sh: W/h h ... F handbook
# error_% ...), out, F (the handbook value), limit (the Aitken limit of the
# three finest), note (a line in the plot), set with gnuplot -e.
set terminal pngcairo size 900,620 font ",12" noenhanced
set output out
set title "Edge crack a/W = 0.45, H/W = 2, plane strain, XEFG with LEFM tip (eq. 5):\nK_I by the interaction integral against the point spacing"
set xlabel "point spacing h (mm), W = 10 mm"
set ylabel "K_I / (sigma sqrt(pi a))"
set logscale x
set xrange [0.09:1.4]
set xtics ("W/10 = 1" 1, "W/20 = 0.5" 0.5, "W/40 = 0.25" 0.25, "W/80 = 0.125" 0.125)
set yrange [F * 0.955:F * 1.075]
set grid front
set key top right spacing 1.15
set label 1 note at graph 0.02, graph 0.05 left front font ",10"
set style fill transparent solid 0.18 noborder
plot [0.09:1.4] (F * 0.97) with filledcurves y1 = (F * 1.03) lc "forest-green" title "handbook +-3 % (pass band)", \
     F with lines lw 2 dt 2 lc "forest-green" title sprintf("handbook F(0.45) = %.4f (Tada / Brown-Srawley)", F), \
     limit with lines lw 1 dt 3 lc "gray40" title sprintf("limit of the three finest (Aitken) = %.4f", limit), \
     data using 2:7 with linespoints pt 7 ps 1.4 lw 2 lc "red" title "XEFG, interaction integral (r_d = 1.5 mm)", \
     data using 2:7:(sprintf("%+.2f %%", $9)) with labels offset 0, 1.2 tc "red" notitle
