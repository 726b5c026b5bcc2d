#!/usr/bin/env bash
# make fig-patch: the crack patch test (the paper's section 3.1 and Fig. 1,
# chapter 2): the full double cantilever beam with an explicit crack
# (figures/fig1/dcb_full.cfg, stage 2) and the half beam with the ligament
# held by symmetry (dcb_half.cfg, no crack), the same load, grid and
# damping, run to the static state (400 ms, about two seconds each).
# match.awk matches the upper half of the full run's points to the half
# run's by position and prints the largest difference of sigma_xx and of
# the positions (also into build/figures/fig-patch.txt); plot.gp draws both
# side by side on one colour scale: build/figures/fig-patch.png.
#
# Both runs write 17 digits (run.precision = "full"), so that the
# difference measured is the runs' own, not that of rounding the output.
# Extra arguments are overrides for both runs (run.time=50 for a short one).
. "$(dirname "$0")/../lib.sh"
set -eo pipefail
RUNS=build/fig-patch
fig_mpm 2
mkdir -p "$RUNS"
for half in full half; do
    "$MPM" "figures/fig1/dcb_$half.cfg" -q -o "$RUNS/$half" run.precision=full \
        run.snapshots=0 "$@" >/dev/null
done
awk -F, -v full="$RUNS/full/particles_final.csv" -f figures/fig-patch/match.awk \
    "$RUNS/full/particles_final.csv" "$RUNS/half/particles_final.csv" \
    > "$RUNS/difference.txt"
grep -v '^label=' "$RUNS/difference.txt" | tee "$OUT/fig-patch.txt"
label=$(sed -n 's/^label=//p' "$RUNS/difference.txt")
fig_need_gnuplot "the runs and $OUT/fig-patch.txt written, no plot"
gnuplot -e "full='$RUNS/full/particles_final.csv'" \
        -e "half='$RUNS/half/particles_final.csv'" \
        -e "label='$label'; out='$OUT/fig-patch.png'" figures/fig-patch/plot.gp
echo "fig-patch: $OUT/fig-patch.png, the difference in $OUT/fig-patch.txt"
