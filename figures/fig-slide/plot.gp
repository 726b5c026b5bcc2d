# make fig-slide: the sliding block's centre displacement s(t) along the
# plate, theta = 30 degrees, mu = 0 and 0.3, cells of 1 and 0.5 mm, against
# the exact curves (gravity grown over the scene's 4 ms ramp, then
# constant); and s / s_exact - 1 against the test's 1 % band.
# Variables (gnuplot -e): runs (the folder of the tables: columns t, s,
# s_exact, y_c - y_c0, interface slip), out.
set terminal pngcairo size 1300,560 font ",11" noenhanced
set output out
g = 0.25
th = pi / 6
R = 4.0                                             # the scene's run.gravity_ramp (ms)
acc(mu) = g * (sin(th) - mu * cos(th))
exact(t, mu) = t < R ? acc(mu) * t**3 / (6 * R) : 0.5 * acc(mu) * (t * t - R * t + R * R / 3)
T(mu) = 0.5 * (R + sqrt(48.0 / acc(mu) - R * R / 3))  # s_exact = 6 mm
T0 = T(0.0)
T3 = T(0.3)
f(m, h) = sprintf("%s/slide_t30_mu%s_h%s.dat", runs, m, h)
set multiplot layout 1, 2 title "Block sliding down a 30 degree incline (gravity tilted; Bardenhagen et al. 2001), stage 4, MUSL, cfl 0.5"
set title "centre displacement along the plate"
set xlabel "t (ms)"
set ylabel "s (mm)"
set grid
set key top left
set xrange [0:15]
set yrange [0:7]
plot exact(x, 0.0) with lines lw 2 dt 2 lc "black" title "exact, mu = 0", \
     exact(x, 0.3) with lines lw 2 dt 3 lc "black" title "exact, mu = 0.3", \
     f("0.00", "1.00") every 10 using 1:2 with lines lw 2 lc "red" title "mu = 0, h = 1 mm", \
     f("0.00", "0.50") every 10 using 1:2 with lines lw 2 lc "orange" title "mu = 0, h = 0.5 mm", \
     f("0.30", "1.00") every 10 using 1:2 with lines lw 2 lc "blue" title "mu = 0.3, h = 1 mm", \
     f("0.30", "0.50") every 10 using 1:2 with lines lw 2 lc "skyblue" title "mu = 0.3, h = 0.5 mm"
set title "s / s_exact - 1 where the test measures it (t >= 0.4 T)"
set ylabel "error (%)"
set yrange [-1:1]
set key bottom right opaque
set style fill transparent solid 0.18 noborder
plot '+' using 1:(-1):(1) with filledcurves lc "forest-green" title "the test's 1 % band", \
     f("0.00", "1.00") every 5 using 1:($1 >= 0.4 * T0 ? 100 * ($2 / $3 - 1) : NaN) with lines lw 2 lc "red" title "mu = 0, h = 1 mm", \
     f("0.00", "0.50") every 5 using 1:($1 >= 0.4 * T0 ? 100 * ($2 / $3 - 1) : NaN) with lines lw 2 lc "orange" title "mu = 0, h = 0.5 mm", \
     f("0.30", "1.00") every 5 using 1:($1 >= 0.4 * T3 ? 100 * ($2 / $3 - 1) : NaN) with lines lw 2 lc "blue" title "mu = 0.3, h = 1 mm", \
     f("0.30", "0.50") every 5 using 1:($1 >= 0.4 * T3 ? 100 * ($2 / $3 - 1) : NaN) with lines lw 2 lc "skyblue" title "mu = 0.3, h = 0.5 mm"
unset multiplot
