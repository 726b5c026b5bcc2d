# Fig. 5 layout and Fig. 6 energy curves of the beam impact (stage 1).
# Called by figures/fig6-onefield/make.sh with: runs (run folder), out (figure
# folder), blowups ("scheme:time ..." of the runs that went unstable).
# Colours as in the paper: USL red, MUSL black, USF blue.

set datafile separator ','
set terminal pngcairo size 900,900 font 'Sans,11'
set output out.'/fig6_onefield.png'

schemes = 'usl musl usf'
names = 'USL MUSL USF'
colours = '#d62728 #000000 #1f3fbf'
hist(i) = runs.'/'.word(schemes, i).'/history.csv'
have(i) = system('test -s '.hist(i).' && echo 1 || echo 0') + 0
blowup(i) = system('for w in '.blowups.'; do [ "${w%%:*}" = '.word(schemes, i).' ] && echo ${w#*:}; done')

# E0 of each run: the total energy in the first row
array E0[3]
avail = ''
do for [i=1:3] {
    E0[i] = 1
    if (have(i)) {
        avail = avail.' '.i
        stats hist(i) skip 1 every ::0::0 using 5 nooutput
        E0[i] = STATS_min
    }
}

set multiplot layout 2,1 title "Beam impact (Fig. 5), one velocity field: energy vs time (cf. Fig. 6)"
set xrange [0:6]
set xlabel 'Time (ms)'
set grid
set key top left

# a blown-up run is drawn until it leaves the frame; its time is in the key
title_of(i) = word(names, i).(blowup(i) ne '' ? sprintf(' (unstable at %.3g ms)', real(blowup(i))) : '')

set ylabel 'Total energy / initial energy'
set yrange [0.9:1.15]
# a cross where a run stopped unstable
do for [w in avail] {
    if (blowup(w+0) ne '') {
        set label sprintf('%s unstable', word(names, w+0)) at real(blowup(w+0)), 1.0 \
            point pt 2 ps 2.5 lc rgb word(colours, w+0) offset 1,-1.2 tc rgb word(colours, w+0)
    }
}
plot for [w in avail] hist(w+0) skip 1 using 2:($5/E0[w+0]) with lines \
         lw 2 lc rgb word(colours, w+0) title title_of(w+0), \
     1 with lines dt 2 lc rgb '#888888' notitle

unset label
set ylabel 'Impactor kinetic energy / initial energy'
set yrange [0:1.1]
set key top right
plot for [w in avail] hist(w+0) skip 1 using 2:($9/E0[w+0]) with lines \
         lw 2 lc rgb word(colours, w+0) title word(names, w+0)
unset multiplot

# ---- Fig. 5: the layout at t = 0 -------------------------------------------
set output out.'/fig6_onefield_scene.png'
set terminal pngcairo size 1000,420 font 'Sans,11'
unset grid
set size ratio -1
set xrange [-48:48]
set yrange [-8:24]
set xlabel 'x (mm)'
set ylabel 'y (mm)'
set key top right
set title "Beam impact layout (Fig. 5): beam (red), impactor (blue), fixed-y support nodes (green)"
lay = runs.'/layout/particles_final.csv'
# particles_final.csv: x,y,vx,vy,...,mass,material,body (body in column 13)
plot lay skip 2 using 1:($13 == 0 ? $2 : 1/0) with points pt 7 ps 0.25 lc rgb '#d62728' title 'beam', \
     lay skip 2 using 1:($13 == 1 ? $2 : 1/0) with points pt 7 ps 0.25 lc rgb '#1f3fbf' title 'impactor', \
     '-' using 1:2 with points pt 9 ps 2.5 lc rgb '#2ca02c' title 'support (v_y = 0)'
-34,-0.9
34,-0.9
e
