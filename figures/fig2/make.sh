#!/bin/bash
# The paper's Fig. 2: sigma_xx along the mid-plane of the cracked DCB,
# CRAMP (stage 2) against a static Q4 finite element analysis on the same
# grid.  The curves come from the test that checks them; what the test
# prints (the openings and the peaks) goes to build/figures/fig2.txt too.
. "$(dirname "$0")/../lib.sh"
set -eo pipefail
TEST=build/stage2/tests/2-fields/scene_fig2
fig_build "$TEST"
FIG2_CSV=$OUT/fig2.csv "$TEST" | grep -v '^\[' | tee "$OUT/fig2.txt"
# the crack tip: the last point of the scene's crack
tip=$(sed -n 's/^cracks = .*\[\([-0-9.eE+]*\), *[-0-9.eE+]*\] *); *} *);.*/\1/p' figures/fig1/dcb_full.cfg)
[ -n "$tip" ] || { echo "fig2: no crack tip in figures/fig1/dcb_full.cfg" >&2; exit 1; }
fig_need_gnuplot "$OUT/fig2.csv and $OUT/fig2.txt written, no plot"
gnuplot -e "data='$OUT/fig2.csv'; out='$OUT/fig2.png'; tip=$tip" figures/fig2/plot.gp
echo "fig2: $OUT/fig2.png"
