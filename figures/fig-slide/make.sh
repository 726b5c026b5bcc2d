#!/usr/bin/env bash
# make fig-slide: the block sliding down an incline (Bardenhagen et al.,
# CMES 2 (2001) 509-522), tests/4-contact/scene_slide.c: the test's runs
# (block 8 x 4 mm on a plate, gravity tilted by theta, cells of 1 and 0.5
# mm) with SLIDE_TABLE set, so that each run writes its centre's slide s(t)
# every step. Draws build/figures/fig-slide.png: s(t) for mu = 0 and 0.3 at
# theta = 30 degrees on both grids against the exact curves (gravity grown
# over 4 ms, then s = 1/2 a (t^2 - 4 t + 16/3), a = |g| (sin theta - mu cos
# theta)), and s / s_exact - 1 with the
# test's 1 % band (over the times the test measures, t >= 0.4 T).
# build/figures/fig-slide.txt: what the test printed (its pass or fail
# included: the figure is drawn either way). About two seconds.
. "$(dirname "$0")/../lib.sh"
set -o pipefail
TEST=build/stage4/tests/4-contact/scene_slide
RUNS=build/fig-slide
fig_build build/stage4/mpm "$TEST"
mkdir -p "$RUNS"
rm -f "$RUNS"/*.dat
txt=$OUT/fig-slide.txt
{
    echo "make fig-slide: $TEST with SLIDE_TABLE=$RUNS, on:"
    echo "  $(fig_cpu)"
    SLIDE_TABLE=$RUNS MPM_BIN=build/stage4/mpm "$TEST" 2>&1
    echo "test exit status: $?"
} | tee "$txt"
for f in slide_t30_mu0.00_h1.00 slide_t30_mu0.00_h0.50 slide_t30_mu0.30_h1.00 slide_t30_mu0.30_h0.50; do
    [ -s "$RUNS/$f.dat" ] || { echo "fig-slide: $RUNS/$f.dat not written" >&2; exit 1; }
done
fig_need_gnuplot "$txt written, no plot"
gnuplot -e "runs='$RUNS'; out='$OUT/fig-slide.png'" figures/fig-slide/plot.gp || exit 1
echo "fig-slide: $OUT/fig-slide.png, $txt"
