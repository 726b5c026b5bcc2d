#!/bin/bash
# The paper's Fig. 1 (top): sigma_xx in the full double cantilever beam with
# an explicit crack, damped to the static state (stage 2, CRAMP).
# Environment: MPM (default build/stage2/mpm).
. "$(dirname "$0")/../lib.sh"
set -eo pipefail
fig_mpm 2
out=$OUT/fig1
mkdir -p "$out"
"$MPM" figures/fig1/dcb_full.cfg -o "$out"
last=$(ls "$out"/cracks_*.csv | tail -n 1)
fig_need_gnuplot "the run is in $out, no plot"
gnuplot -e "points='$out/particles_final.csv'; crack='$last'; \
            out='$OUT/fig1.png'; title='Fig. 1 (top): CRAMP, full DCB with an explicit crack'" \
        figures/fig1/plot.gp
echo "fig1: $OUT/fig1.png"
