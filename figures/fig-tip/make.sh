#!/usr/bin/env bash
# make fig-tip (issue 7): the DCB with its crack tip on a grid node and
# mid-cell, on three grids (tests/3-crossing/scenes/tip_*.cfg), run to the
# static state by build/stage3/mpm; sigma_xx along the ligament against a
# converged static Q4 analysis, read at the node's x, at the same distance
# from the (moved) tip, and sampled as the MPM samples.  Prints the tables
# (the study of chapter 3, "The tip on a node") and draws
# build/figures/fig-tip.png.
#
# About three minutes on one core, mostly the six runs.  The FEA takes
# h = 0.25 and 0.125 mm (10 s); TIP_FEA_H=0.125 takes h = 0.125 and 0.0625
# mm instead (about 2 minutes and 4.3 GB of memory; the tables change by
# less than 0.3 percentage points).
. "$(dirname "$0")/../lib.sh"
set -eo pipefail
TEST=build/stage3/tests/3-crossing/scene_tip_on_node
RUNS=build/fig-tip
fig_mpm 3
fig_build "$TEST"
mkdir -p "$OUT/fig-tip" "$RUNS"
for s in tip_node_2mm tip_mid_51 tip_node_1mm tip_mid_101 tip_node_05mm tip_mid_201; do
    "$MPM" "tests/3-crossing/scenes/$s.cfg" -q -o "$RUNS/$s" run.snapshots=1
done
TIP_FEA_H=${TIP_FEA_H:-0.25} TIP_STUDY=$RUNS TIP_CSV_DIR=$OUT/fig-tip "$TEST" | tee "$OUT/fig-tip.txt"
fig_need_gnuplot "$OUT/fig-tip.txt written, no plot"
gnuplot -e "dir='$OUT/fig-tip'; out='$OUT/fig-tip.png'" figures/fig-tip/plot.gp
echo "fig-tip: $OUT/fig-tip.png, tables in $OUT/fig-tip.txt"
