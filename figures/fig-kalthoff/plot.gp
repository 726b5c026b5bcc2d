# make fig-kalthoff's plot (figures/fig-kalthoff/make.sh writes the data):
#   gnuplot -e "runs='build/fig-kalthoff'; out='...png'; kxt=90; names='h1 h1.25 h1.667 h2.5'; kinks='70.53 69.91 70.53 -'; cr=2802.7" plot.gp
# (kinks: each run's first kink, degrees, - none; cr: Rayleigh's speed, m/s)
# (a) the paths on the upper half plate with the notch and the experiment's
#     70-degree line; (b) the path length from the notch tip against time,
#     with a line of slope c_R from each first event; (c) the energy
#     balance's error against time, % of the work put in by the end.
set terminal pngcairo size 1800,640 font ",12" enhanced
set output out
set multiplot layout 1,3 margins 0.05,0.98,0.12,0.9 spacing 0.07,0.1
n = words(names)
col(i) = word('#D55E00 #0072B2 #009E73 #CC79A7', i)
hh(i) = substr(word(names, i), 2, 99)
lab(i) = word(kinks, i) eq '-' ? sprintf("h = %s mm: no growth", hh(i)) : \
         sprintf("h = %s mm: first kink %s{/Symbol \260}", hh(i), word(kinks, i))

# (a)
set title sprintf("(a) the crack paths at %g {/Symbol m}s (upper half)", kxt)
set xlabel "x (mm), along the impact (struck at x = 0, 0 < y < 25)"
set ylabel "y (mm), from the symmetry line"
set xrange [0:100]
set yrange [0:100]
set size ratio -1
set grid
set key bottom right opaque
set object 1 rect from 0,0 to 100,100 fs empty border lc rgb '#888888'
t70 = 70 * pi / 180
set arrow 1 from 50,25 to 50 + 75 / tan(t70), 100 nohead lw 1.5 dt 2 lc rgb '#000000'
set label 1 "experiment, about 70{/Symbol \260}" at 66,92 right
plot '+' using (0):(25):(50):(0) every ::0::0 with vectors nohead lw 3 lc rgb '#888888' title "notch", \
     for [i=1:n] runs.'/path_'.word(names, i).'.txt' every ::1 using 1:2 with linespoints lw 2 pt 7 ps 0.4 \
         lc rgb col(i) title lab(i)
unset arrow 1
unset label 1
unset object 1

# (b)
set title "(b) the path length from the notch tip against time"
set xlabel "t ({/Symbol m}s)"
set ylabel "path length (mm)"
set size noratio
set autoscale
set xrange [0:kxt]
set yrange [0:100]
set key top left opaque
stats runs.'/events_'.word(names, 1).'.txt' using 2 nooutput name 'T1'
t1 = T1_min
plot for [i=1:n] runs.'/events_'.word(names, i).'.txt' using 2:5 with linespoints lw 2 pt 7 ps 0.4 \
         lc rgb col(i) title sprintf("h = %s mm", hh(i)), \
     [t1:kxt] (x - t1) * cr / 1000 with lines lw 1.5 dt 2 lc rgb '#000000' \
         title sprintf("slope c_R = %.0f m/s from h = %s's first event", cr, hh(1))

# (c)
set title "(c) the energy balance's error"
set xlabel "t ({/Symbol m}s)"
set ylabel "in - kinetic - strain - cohesive (% of in at the end)"
set key bottom right opaque
set autoscale y
plot for [i=1:n] runs.'/energy_'.word(names, i).'.txt' using 1:4 with lines lw 2 \
         lc rgb col(i) title sprintf("h = %s mm", hh(i))
unset multiplot
