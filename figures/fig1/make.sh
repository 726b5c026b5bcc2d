#!/bin/bash
# The paper's Fig. 1 (top): sigma_xx in the full double cantilever beam with
# an explicit crack, damped to the static state (stage 2, CRAMP).
set -euo pipefail
out=build/figures/fig1
mkdir -p "$out"
build/stage2/mpm figures/fig1/dcb_full.cfg -o "$out"
last=$(ls "$out"/cracks_*.csv | tail -n 1)
gnuplot -e "points='$out/particles_final.csv'; crack='$last'; \
            out='build/figures/fig1.png'; title='Fig. 1 (top): CRAMP, full DCB with an explicit crack'" \
        figures/fig1/plot.gp
echo "fig1: build/figures/fig1.png"
