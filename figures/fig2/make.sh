#!/bin/bash
# The paper's Fig. 2: sigma_xx along the mid-plane of the cracked DCB,
# CRAMP (stage 2) against a static Q4 finite element analysis on the same
# grid.  The curves come from the test that checks them.
set -euo pipefail
mkdir -p build/figures
make --no-print-directory build/stage2/tests/2-fields/scene_fig2
FIG2_CSV=build/figures/fig2.csv build/stage2/tests/2-fields/scene_fig2 | grep -v '^\['
# the crack tip: the last point of the scene's crack
tip=$(sed -n 's/^cracks = .*\[\([-0-9.eE+]*\), *[-0-9.eE+]*\] *); *} *);.*/\1/p' figures/fig1/dcb_full.cfg)
[ -n "$tip" ] || { echo "fig2: no crack tip in figures/fig1/dcb_full.cfg" >&2; exit 1; }
gnuplot -e "data='build/figures/fig2.csv'; out='build/figures/fig2.png'; tip=$tip" figures/fig2/plot.gp
echo "fig2: build/figures/fig2.png"
