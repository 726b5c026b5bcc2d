#!/usr/bin/env bash
# make fig-bars: two identical elastic bars colliding head-on from a gap
# (issue 25; tests/4-contact/scene_bars.c, its study of the cell): the
# rebound against the exact exchange of velocities as the cell shrinks,
# N = 20 ... 160 cells a bar (bars two cells tall: nu = 0 in plane stress
# makes a bar 1D whatever its height), for MUSL and USAVG at cfl 0.25 (USL
# goes unstable once the bars part; USF's energy grows by hundreds of % from
# 80 cells on, its one-field run's too: chapter 4b), beside the same bars run as one velocity field and the lumped-mass
# chain of N elements on a perfect wall (what a nodal scheme can give).
# Every bound of the test (contact start within h/2 of the touch, duration
# and rebound against the one field, energy, momentum) is checked at every
# N; the table says from which N the rebound is within 2 % of v0 of the
# exact one. Writes build/figures/fig-bars.png and fig-bars.txt. The cost
# grows as N^2 (points and steps both as N): 320 cells cost four times
# 160 (about 10 s a scheme), and there MUSL's energy bound fails
# (chapter 4b), so the default stops at 160.
#
# Environment: BARS_CELLS (default "20 40 80 160"), BARS_SCHEMES
# ("musl usavg"), BARS_CFL ("0.25").
. "$(dirname "$0")/../lib.sh"
set -o pipefail
TEST=build/stage5/tests/4-contact/scene_bars
fig_build build/stage5/mpm "$TEST"
export BARS_CELLS=${BARS_CELLS:-"20 40 80 160"}
export BARS_SCHEMES=${BARS_SCHEMES:-"musl usavg"}
export BARS_CFL=${BARS_CFL:-"0.25"}
txt=$OUT/fig-bars.txt
mkdir -p build/fig-bars
start=$(fig_now)
{
    echo "make fig-bars: $TEST with BARS_CELLS=\"$BARS_CELLS\" BARS_SCHEMES=\"$BARS_SCHEMES\" BARS_CFL=\"$BARS_CFL\", on:"
    echo "  $(fig_cpu)"
    MPM_BIN=build/stage5/mpm "$TEST" 2>&1
    echo "$?" >build/fig-bars/rc
    echo "test exit status: $(cat build/fig-bars/rc)"
} | tee "$txt"
rc=$(cat build/fig-bars/rc)
echo "  wall time: $(fig_since "$start") s" | tee -a "$txt"
dat=build/fig-bars/rows.dat
# rows: N scheme cfl rebound one-field chain dur energy
awk '$1 ~ /^[0-9]+$/ && NF >= 11 { gsub("%", ""); print $1, $2, $3, $4, $5, $6, $8, $10 }' \
    "$txt" | sort -s -k2,2 -k1,1n >"$dat"             # each scheme's rows together
[ -s "$dat" ] || { echo "fig-bars: no rows in $txt" >&2; exit 1; }
fig_need_gnuplot "$txt written, no plot"
gnuplot -e "dat='$dat'; out='$OUT/fig-bars.png'; schemes='$BARS_SCHEMES'" \
    figures/fig-bars/plot.gp || exit 1
echo "fig-bars: $OUT/fig-bars.png, $txt"
exit "$rc"
