# The beam impact with contact between bodies (stage 4): the impactor's
# kinetic energy against time (the curve by which the paper times the
# impact, 0.4 to 4.2 ms) and the total energy, for each scheme, with the
# one-field MUSL run for comparison. Called by figures/fig5/make.sh with:
# runs (run folder: <run>/curve.csv and <run>/times.txt), out (figure
# folder), blowups ("scheme:time ..." of the runs that went unstable),
# usfcfl (the step of the USF run).
# Colours as in the paper: USL red, MUSL black, USF blue; one field grey.

set datafile separator ','
set terminal pngcairo size 900,900 font 'Sans,11'
set output out.'/fig5.png'

schemes = 'usl musl usf'
names = 'USL MUSL USF'
colours = '#d62728 #000000 #1f3fbf'
curve(i) = runs.'/contact-'.word(schemes, i).'/curve.csv'
have(i) = system('test -s '.curve(i).' && echo 1 || echo 0') + 0
times(i) = system('cat '.runs.'/contact-'.word(schemes, i).'/times.txt 2>/dev/null')
blowup(i) = system('for w in '.blowups.'; do [ "${w%%:*}" = '.word(schemes, i).' ] && echo ${w#*:}; done')
one = runs.'/one-field-musl/curve.csv'
have_one = system('test -s '.one.' && echo 1 || echo 0') + 0

avail = ''
do for [i=1:3] { if (have(i)) { avail = avail.' '.i } }

cfl(i) = (i == 3 ? usfcfl : '0.1')
title_of(i) = word(names, i).' (cfl '.cfl(i).')'.\
    (blowup(i) ne '' ? sprintf(', unstable at %.3g ms', real(blowup(i))) : '')

set multiplot layout 2,1 title "Beam impact (Fig. 5) with frictionless contact between the bodies"
set xrange [0:6]
set xlabel 'Time (ms)'
set grid
set key at 3.9, 1.07 right

# contact start (up triangle) and leave (down triangle) of each run
do for [w in avail] {
    t = times(w+0)
    if (word(t, 1) ne '-' && word(t, 1) ne '') {
        set label point pt 9 ps 1.6 lc rgb word(colours, w+0) at real(word(t, 1)), 1.0
    }
    if (word(t, 2) ne '-' && word(t, 2) ne '') {
        set label point pt 11 ps 1.6 lc rgb word(colours, w+0) at real(word(t, 2)), 0.05
    }
}
set label 'paper: impact from about 0.4 to 4.2 ms' at 0.5, 0.6 tc rgb '#555555'
set arrow from 0.4, 0.55 to 4.2, 0.55 heads size 0.08,90 lc rgb '#555555'
set ylabel 'Impactor kinetic energy / initial'
set yrange [0:1.1]
plot for [w in avail] curve(w+0) skip 1 using 1:2 with lines \
         lw 2 lc rgb word(colours, w+0) title title_of(w+0), \
     (have_one ? one : '/dev/null') skip 1 using 1:2 with lines lw 2 dt 2 \
         lc rgb '#888888' title 'MUSL, one velocity field (sticks)', \
     1/0 with points pt 9 ps 1.6 lc rgb '#000000' title 'contact starts', \
     1/0 with points pt 11 ps 1.6 lc rgb '#000000' title 'impactor leaves'

unset label
unset arrow
set ylabel 'Total energy / initial'
set yrange [0.9:1.15]
set key top left
plot for [w in avail] curve(w+0) skip 1 using 1:3 with lines \
         lw 2 lc rgb word(colours, w+0) title title_of(w+0), \
     (have_one ? one : '/dev/null') skip 1 using 1:3 with lines lw 2 dt 2 \
         lc rgb '#888888' title 'MUSL, one velocity field', \
     1 with lines dt 3 lc rgb '#888888' notitle
unset multiplot
