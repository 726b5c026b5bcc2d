#!/usr/bin/env bash
# make fig3: the paper's Fig. 3, two disks with central cracks colliding and
# bouncing apart with frictionless crack contact (stage 4).  Runs the full
# scene figures/fig3/cracked_disks.cfg (40 ms, CFL 0.1) through the scene
# test's study mode, which watches every step that no point crosses its
# crack and writes the cracks' openings and four snapshots (the paper's
# frames A-D: t = 0, 7, 12 and 18 ms); draws build/figures/fig3.png
# (sigma_xx with the cracks) and build/figures/fig3-openings.png.
# About 10 s on one core.
. "$(dirname "$0")/../lib.sh"
set -eo pipefail
TEST=build/stage4/tests/4-contact/scene_fig3
fig_build build/stage4/mpm "$TEST"
mkdir -p "$OUT/fig3"
start=$(fig_now)
FIG3_OUT=$OUT/fig3 "$TEST" | tee "$OUT/fig3.txt"
echo "  wall time of the run: $(fig_since "$start") s" | tee -a "$OUT/fig3.txt"
times=$(for k in 0 1 2 3; do sed -n '1s/# t = \([0-9.e+-]*\) ms/\1/p' "$OUT/fig3/snap_$k.csv"; done | tr '\n' ' ')
fig_need_gnuplot "the run and $OUT/fig3.txt written, no plot"
gnuplot -e "dir='$OUT/fig3'; out='$OUT/fig3.png'; times='$times'" figures/fig3/plot.gp
gnuplot -e "dir='$OUT/fig3'; out='$OUT/fig3-openings.png'" figures/fig3/openings.gp
echo "fig3: $OUT/fig3.png, $OUT/fig3-openings.png (numbers in $OUT/fig3.txt)"
