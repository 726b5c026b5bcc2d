#!/usr/bin/env bash
# make fig4: the paper's Fig. 4, five PMMA disks in a row struck on the left
# at 6 m/s, the central disk cracked along the loading direction; contact
# between bodies (a contact group per disk, frictionless) and frictionless
# crack contact (stage 4).  Runs the full scene figures/fig4/five_disks.cfg
# (58,000 points, 0.1 ms, 1966 steps) through the scene test's study mode,
# which watches every step that no point crosses the crack, and draws
#   build/figures/fig4.png          photoelastic fringes cos(k_f dsigma)
#                                   (eq. 23, k_f = 0.0889/MPa) when the wave
#                                   front reaches the last disk (its first
#                                   dark fringe), and the cracked disk larger;
#   build/figures/fig4-contact.png  the crack's contact nodes (and those
#                                   between bodies) and its opening against
#                                   time.
# Numbers in build/figures/fig4.txt.  About 15 s on one core.
. "$(dirname "$0")/../lib.sh"
set -eo pipefail
TEST=build/stage4/tests/4-contact/scene_fig4
fig_build build/stage4/mpm "$TEST"
mkdir -p "$OUT/fig4"
start=$(fig_now)
FIG4_OUT=$OUT/fig4 "$TEST" | tee "$OUT/fig4.txt"
echo "  wall time of the run: $(fig_since "$start") s" | tee -a "$OUT/fig4.txt"
t=$(sed -n '1s/# t = \([0-9.e+-]*\) ms/\1/p' "$OUT/fig4/snap.csv")
t0=$(awk -F, 'NR > 1 && $3 > 0 { print $1; exit }' "$OUT/fig4/contact.csv")
t3=$(awk -F, 'NR > 1 && 0.0889 * $5 >= 3.14159265358979 { print $1; exit }' "$OUT/fig4/contact.csv")
echo "  figure time: $t ms, $(awk -v a="$t" -v b="$t0" 'BEGIN { printf "%.4g", a - b }') ms after the impactor met disk 1 (end of the first step in contact, $t0 ms)" | tee -a "$OUT/fig4.txt"
fig_need_gnuplot "the run and $OUT/fig4.txt written, no plot"
gnuplot -e "dir='$OUT/fig4'; out='$OUT/fig4.png'; t=$t; t0=$t0" figures/fig4/plot.gp
gnuplot -e "dir='$OUT/fig4'; out='$OUT/fig4-contact.png'; t=$t; t0=$t0; t3=$t3" figures/fig4/contact.gp
echo "fig4: $OUT/fig4.png, $OUT/fig4-contact.png (numbers in $OUT/fig4.txt)"
