# make fig-growth's plot (figures/fig-growth/make.sh writes the data):
#   gnuplot -e "runs='build/fig-growth'; out='...png'; kxt=90; hm='1'; hx='1'; hms='2 1.5 1'; hxs='2 1.5 1'; kx='2000 1000'; ft='1e-3'; kkm='70.7'; kkx='- 70.5'" plot.gp
# (kxt: the plate's time, microseconds)
# (kkm, kkx: the first kinks, degrees, of CRAMP and of each XEFG f_t; - none)
# (a) DCB: crack length against the opening, CRAMP and XEFG (finest h of
#     each) and the FEA's G(a) = G_c; (b) the DCB's paths; (c) Kalthoff-
#     Winkler's paths near the notch tip with the experiment's 70 degrees;
#     (d) the DCB's opening error against the time loop's wall time;
#     (e) the DCB's G/G_c at each event against the crack length (G the
#     FEA's G(a) at the event's opening), every resolution of both.
set terminal pngcairo size 2100,1100 font ",12" enhanced
set output out
set multiplot layout 2,3 margins 0.05,0.98,0.07,0.95 spacing 0.06,0.1
cm = '#0072B2'; cx = '#D55E00'; cf = '#000000'; ce = '#009E73'
# the DCB paths' largest |y|, for (b)'s key
stats runs.'/path_dcb-mpm.txt' using (abs($2)) nooutput name 'PM'
stats runs.'/path_dcb-xefg.txt' using (abs($2)) nooutput name 'PX'

# (a)
set title "(a) DCB: crack length against the imposed opening"
set xlabel "opening {/Symbol D} at the loaded end, both arms (mm)"
set ylabel "crack length a (mm)"
set key top left
set grid
set xrange [1.5:*]
set yrange [49:*]
plot runs.'/fea_0.txt' using 4:1 with lines lw 3 lc rgb cf title "FEA, G(a) = G_c (end at x = 0)", \
     runs.'/fea_'.sprintf('%g', hx / 2.0).'.txt' using 4:1 with lines lw 1.5 dt 2 lc rgb cf title sprintf("FEA, end at x = %g (XEFG's)", hx / 2.0), \
     runs.'/curve_dcb-mpm-'.hm.'.txt' using 1:2 with lines lw 2 lc rgb cm title sprintf("CRAMP, J = G_c, cells %s mm", hm), \
     runs.'/curve_dcb-xefg-'.hx.'.txt' using 1:2 with lines lw 2 lc rgb cx title sprintf("XEFG, cohesive f_t = %s MPa, h = %s mm", ft, hx)

# (b)
set title "(b) DCB: crack paths at 600 ms (initial crack to x = 50)"
set xlabel "x (mm)"
set ylabel "y (mm)"
set xrange [0:100]
set yrange [-18:18]
set size ratio -1
set key bottom left opaque
set object 1 rect from 0,-18 to 100,18 fs empty border lc rgb '#888888'
plot runs.'/path_dcb-mpm.txt' using 1:2 with lines lw 3 lc rgb cm title sprintf("CRAMP (largest |y| %.2g mm)", PM_max), \
     runs.'/path_dcb-xefg.txt' using 1:2 with linespoints lw 2 pt 7 ps 0.5 lc rgb cx title sprintf("XEFG (largest |y| %.3g mm)", PX_max)
unset object 1

# (c)
set title sprintf("(c) Kalthoff-Winkler, upper half: crack paths at %g {/Symbol m}s", kxt)
set xlabel "x (mm), along the impact (struck at x = 0, 0 < y < 25)"
set ylabel "y (mm), from the symmetry line"
set xrange [0:100]
set yrange [0:100]
set key bottom right opaque
set object 2 rect from 0,0 to 100,100 fs empty border lc rgb '#888888'
t70 = 70 * pi / 180
set arrow 1 from 50,25 to 50 + 75 / tan(t70), 100 nohead lw 1.5 dt 2 lc rgb ce
set label 1 "experiment, about 70{/Symbol \260}" at 66,75 right tc rgb ce
nk = words(kx)
kc(i) = word('#D55E00 #CC79A7 #E69F00 #56B4E9', i)
kt(i) = word(kkx, i) eq '-' ? sprintf("XEFG, f_t = %s MPa: no growth", word(kx, i)) : \
        sprintf("XEFG, f_t = %s MPa: first kink %s{/Symbol \260}", word(kx, i), word(kkx, i))
plot '+' using (0):(25):(50):(0) every ::0::0 with vectors nohead lw 3 lc rgb '#888888' title "notch (G_c = G_f = 22.1 N/mm)", \
     runs.'/path_kw-mpm.txt' using 1:2 with linespoints lw 2.5 pt 7 ps 0.6 lc rgb cm \
         title sprintf("CRAMP: first kink %s{/Symbol \260}", kkm), \
     for [i=1:nk] runs.'/path_kw-xefg-'.word(kx, i).'.txt' using 1:2 with linespoints lw 2 pt 5 ps 0.4 lc rgb kc(i) \
         title kt(i)
unset arrow 1
unset label 1
unset object 2

# (d)
set title "(d) DCB: opening error against cost"
set xlabel "wall time of the time loop (s)"
set ylabel "error of the opening {/Symbol D} against the FEA (%)"
set size noratio
set logscale xy
set autoscale
set datafile missing '-'
set key top right opaque
plot runs.'/plot_cost.txt' index 0 using 1:(100 * $2) with linespoints lw 2 pt 7 ps 1.3 lc rgb cm title "CRAMP, |error| at the first event (a = 50 mm)", \
     '' index 0 using 1:(100 * $3) with linespoints lw 2 dt 2 pt 6 ps 1.3 lc rgb cm title "CRAMP, RMS error at a = 54, 58, 62, 66 mm", \
     '' index 0 using 1:(100 * $2):4 with labels offset 0,-1 tc rgb cm notitle, \
     '' index 1 using 1:(100 * $2) with linespoints lw 2 pt 5 ps 1.3 lc rgb cx title "XEFG, |error| at the first event (a = 50 mm)", \
     '' index 1 using 1:(100 * $3) with linespoints lw 2 dt 2 pt 4 ps 1.3 lc rgb cx title "XEFG, RMS error at a = 54, 58, 62, 66 mm", \
     '' index 1 using 1:(100 * $2):4 with labels offset 0,-1 tc rgb cx notitle

# (e)
set title "(e) DCB: the energy release rate at each event against the crack length"
set xlabel "crack length a before the event (mm)"
set ylabel "G / G_c (G: the FEA's G(a) at the event's opening)"
unset logscale xy
set autoscale
set xrange [49:76]
set yrange [0.78:1.06]
set key bottom center maxrows 4 opaque
pm(i) = int(word('7 9 5', i))
px(i) = int(word('6 8 4', i))
set samples 2
plot 1 with lines lw 2 lc rgb cf title "G = G_c", \
     for [i=1:words(hms)] runs.'/g_dcb-mpm-'.word(hms, i).'.txt' using 1:2 with linespoints lw 1.5 pt pm(i) ps 1 lc rgb cm \
         title sprintf("CRAMP, cells %s mm", word(hms, i)), \
     for [i=1:words(hxs)] runs.'/g_dcb-xefg-'.word(hxs, i).'.txt' using 1:2 with linespoints lw 1.5 dt 2 pt px(i) ps 1 lc rgb cx \
         title sprintf("XEFG, h = %s mm", word(hxs, i))
unset multiplot
