# The paper's Fig. 4 (bottom): the calculated photoelastic pattern
# cos(k_f sqrt((s_xx - s_yy)^2 + 4 t_xy^2)) (eq. 23, k_f = 0.0889 per MPa),
# light +1 to dark -1, on the points of the five disks when the wave front
# reaches the last disk; below, the cracked central disk larger.  The
# impactor (not PMMA) is drawn plain; the crack in red.
# Variables (gnuplot -e): dir (snap.csv, crack.csv), out, t, t0.
set terminal pngcairo size 1600,1060 font ",11"
set termoption noenhanced
set output out
set datafile separator ","
kf = 0.0889
h = 0.27        # half the point spacing (0.25 mm), a little more so that squares overlap
fringe(sxx, syy, sxy) = cos(kf * sqrt((sxx - syy)**2 + 4 * sxy**2))
set palette gray
set cbrange [-1:1]
unset colorbox
set key off
set size ratio -1
set object 1 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb "#1c2a3a" fillstyle solid noborder
snap = dir."/snap.csv"
crack = dir."/crack.csv"
set multiplot title sprintf("Fig. 4: five PMMA disks struck at 6 m/s, fringes cos(k_f dsigma), k_f = 0.0889/MPa, at t = %.4g ms (%.4g ms after the impactor met disk 1): the front has reached the last disk", t, t - t0)
set origin 0, 0.56
set size 1, 0.40
set xrange [-22:137]
set yrange [-17:17]
set xlabel "x (mm)"
set ylabel "y (mm)"
plot snap using 1:2:($1-h):($1+h):($2-h):($2+h):($6 == 0 ? 1/0 : fringe($3, $4, $5)) skip 2 with boxxy fillstyle solid noborder fillcolor palette, \
     snap using ($6 == 0 ? $1 : 1/0):2:($1-h):($1+h):($2-h):($2+h) skip 2 with boxxy fillstyle solid noborder fillcolor rgb "#8a8a8a", \
     crack using 1:2 with lines lw 2 lc rgb "#e02020"
set origin 0.2, 0.0
set size 0.6, 0.55
set title "the cracked disk (d3): fringes gather at the crack tips"
set xrange [43:77]
set yrange [-16:16]
plot snap using 1:2:($1-h):($1+h):($2-h):($2+h):($6 == 0 ? 1/0 : fringe($3, $4, $5)) skip 2 with boxxy fillstyle solid noborder fillcolor palette, \
     crack using 1:2 with lines lw 2 lc rgb "#e02020"
unset multiplot
