# Fig. 1 (bottom): sigma_xx of the half DCB's points in the static state.
# Called by figures/fig1b/make.sh with: pts (x0,y0,x,y,sigma_xx per line),
# out (PNG path), mag (displacement magnification).
set datafile separator ','
set terminal pngcairo size 1200,420 font 'Sans,11'
set output out
set size ratio -1
set xrange [-3:103]
set yrange [-3:27]
set xlabel 'x (mm)'
set ylabel 'y (mm)'
set title sprintf("Half DCB (Fig. 1, bottom): sigma_{xx} in kPa, P = 0.1 mN, displacements x %g", mag)
# blue compression, red tension, zero in the middle (green)
set palette defined (-1 '#00008f', -0.6 '#0060ff', -0.25 '#00e0ff', 0 '#40ff80', \
                     0.25 '#ffe000', 0.6 '#ff4000', 1 '#8f0000')
# the bending stress at the root of an arm clamped at the tip,
# 6 P a / (t h^2) = 0.091 kPa, sets the scale; the crack tip saturates
set cbrange [-0.12:0.12]
set cblabel 'sigma_{xx} (kPa)'
unset key
# the symmetry condition (held nodes) and the crack faces
set arrow from 50,0 to 100,0 nohead lw 3 lc rgb '#404040' front
set label 'y-fixed ligament nodes' at 75,-1.8 center front
set label 'crack' at 25,-1.8 center front
set arrow from 1,21.5 to 1,25.5 lw 2 lc rgb 'black' front
set label 'P' at 2,24.5 front
plot pts using ($1 + mag * ($3 - $1)):($2 + mag * ($4 - $2)):(1000 * $5) \
     with points pt 5 ps 0.3 lc palette
