# Fig. 6: total energy against time for the four schemes in the beam impact
# with contact (stage 5), and the Fig. 5 layout. Called by
# figures/fig6/make.sh with: runs (run folder: <scheme>/curve.csv), out
# (figure folder), blowups ("scheme:time ..." of the runs that went
# unstable). Colours as in the paper: USL red, MUSL black, USF blue,
# USAVG green.

set datafile separator ','
set terminal pngcairo size 900,1200 font 'Sans,11'
set output out.'/fig6.png'

schemes = 'usl musl usf usavg'
names = 'USL MUSL USF USAVG'
colours = '#d62728 #000000 #1f3fbf #2ca02c'
curve(i) = runs.'/'.word(schemes, i).'/curve.csv'
have(i) = system('test -s '.curve(i).' && echo 1 || echo 0') + 0
blowup(i) = system('for w in '.blowups.'; do [ "${w%%:*}" = '.word(schemes, i).' ] && echo ${w#*:}; done')

avail = ''
do for [i=1:4] { if (have(i)) { avail = avail.' '.i } }
title_of(i) = word(names, i).(blowup(i) ne '' ? sprintf(' (unstable at %.3g ms)', real(blowup(i))) : '')

set multiplot layout 3,1 title "Beam impact with contact (Fig. 5), cfl 0.1: energy against time (cf. Fig. 6)"
set xrange [0:6]
set xlabel 'Time (ms)'
set grid

do for [w in avail] {
    if (blowup(w+0) ne '') {
        set label sprintf('%s unstable', word(names, w+0)) at real(blowup(w+0)), 1.0 \
            point pt 2 ps 2.5 lc rgb word(colours, w+0) offset 1,-1.2 tc rgb word(colours, w+0)
    }
}
set ylabel 'Total energy / initial'
set yrange [0.9:1.3]
set key top left
plot for [w in avail] curve(w+0) skip 1 using 1:2 with lines \
         lw 2 lc rgb word(colours, w+0) title title_of(w+0), \
     1 with lines dt 3 lc rgb '#888888' notitle

set ylabel 'Total energy / initial (zoom)'
set yrange [0.985:1.01]
set key bottom left
plot for [w in avail] curve(w+0) skip 1 using 1:2 with lines \
         lw 2 lc rgb word(colours, w+0) title word(names, w+0), \
     1.0018 with lines dt 2 lc rgb '#2ca02c' title 'paper: USAVG within +-0.18 %', \
     0.9982 with lines dt 2 lc rgb '#2ca02c' notitle

unset label
set label 'paper: impact from about 0.4 to 4.2 ms' at 0.5, 0.6 tc rgb '#555555'
set arrow from 0.4, 0.55 to 4.2, 0.55 heads size 0.08,90 lc rgb '#555555'
set ylabel 'Impactor kinetic energy / initial'
set yrange [0:1.1]
set key bottom right
plot for [w in avail] curve(w+0) skip 1 using 1:3 with lines \
         lw 2 lc rgb word(colours, w+0) title word(names, w+0)
unset arrow
unset label
unset multiplot

# ---- Fig. 5: the layout at t = 0 -------------------------------------------
set output out.'/fig6_scene.png'
set terminal pngcairo size 1000,420 font 'Sans,11'
unset grid
set size ratio -1
set xrange [-48:48]
set yrange [-8:24]
set xlabel 'x (mm)'
set ylabel 'y (mm)'
set key top right
set title "Beam impact layout (Fig. 5): beam (red), impactor (blue), supports (green), fixed nodes (squares)"
lay = runs.'/layout/particles_final.csv'
# particles_final.csv: x,y,vx,vy,...,mass,material,body (body in column 13)
plot lay skip 2 using 1:($13 == 0 ? $2 : 1/0) with points pt 7 ps 0.25 lc rgb '#d62728' title 'beam', \
     lay skip 2 using 1:($13 == 1 ? $2 : 1/0) with points pt 7 ps 0.25 lc rgb '#1f3fbf' title 'impactor', \
     lay skip 2 using 1:($13 >= 2 ? $2 : 1/0) with points pt 7 ps 0.25 lc rgb '#2ca02c' title 'supports', \
     '-' using 1:2 with points pt 4 ps 1 lc rgb '#555555' title 'fixed nodes (x, y)'
-37,-5
-36,-5
-35,-5
-34,-5
-33,-5
-32,-5
-31,-5
31,-5
32,-5
33,-5
34,-5
35,-5
36,-5
37,-5
-37,-4
-36,-4
-35,-4
-34,-4
-33,-4
-32,-4
-31,-4
31,-4
32,-4
33,-4
34,-4
35,-4
36,-4
37,-4
-37,-3
-36,-3
-35,-3
-34,-3
-33,-3
-32,-3
-31,-3
31,-3
32,-3
33,-3
34,-3
35,-3
36,-3
37,-3
e
