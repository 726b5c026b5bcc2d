#!/usr/bin/env bash
# make fig-petersson: Petersson's notched beam (chapter 6b, "Petersson's
# beam"; tests/6-xefg/scenes/petersson.cfg, tests/6-xefg/scene_petersson.c):
# load against mid-span deflection of the XEFG beam with a cohesive
# ligament, at three point spacings (h = 20, 13.33 and 10 mm), against the
# two points of Petersson's measured curve that code_aster's validation
# case ssnp166a checks (774 N at 0.365 mm, 598 N at 0.607 mm).  Two more
# runs at h = 20: the density halved (the curve must not move: the run is
# quasi-static) and linear softening instead of exponential.  Then the
# crack grown from the notch (tests/6-xefg/scenes/petersson_grow.cfg,
# growth criterion = "tip") at h = 13.33, 10 and 6.67 mm (at h = 20 its
# peak is the ringing after the notch's first insertion: chapter 6c).
#
# The load: P = dW / d delta, W the work of the held places (history.csv's
# xefg_held_work; the supports do no work), delta the deflection of the
# held top nodes (0.005 mm/ms ramped in over 20 ms), the difference of
# consecutive history rows (curve.awk).  The work to separation: the area
# under the curve to 2 mm plus the tail beyond, P_e delta_e (P falls as
# 1 / delta^2 far out; P_e the mean load over the last 0.05 mm), against
# G_f b (D - a0) = 685 N mm.
#
# Writes build/figures/fig-petersson.png and build/figures/fig-petersson.txt;
# runs under build/fig-petersson/.  About half an hour of one core, the
# grown h = 6.67 run (some 16 minutes) the most of it.  Environment: MPM
# (default build/stage6/mpm), SPACINGS (default "20 13.333333333333334
# 10"), GROW_SPACINGS (the grown crack's three, default
# "13.333333333333334 10 6.666666666666667"; "$SPACINGS" for the set
# before, some 15 minutes less).
. "$(dirname "$0")/../lib.sh"
SPACINGS=${SPACINGS:-"20 13.333333333333334 10"}
GROW_SPACINGS=${GROW_SPACINGS:-"13.333333333333334 10 6.666666666666667"}
RUNS=build/fig-petersson
SCENE=tests/6-xefg/scenes/petersson.cfg
GROW=tests/6-xefg/scenes/petersson_grow.cfg
txt=$OUT/fig-petersson.txt
mkdir -p "$RUNS"
load0=$(fig_load)
fig_mpm 6

# the overrides of spacing H (the scene is h = 20): grid, body, the boxes
# of the supports and the load, the crack from below the beam to above it
# (with a second argument "grow": only the notch, to y = 100)
ovh() {
    awk -v h="$1" -v grow="$2" '
    function f(x,  s) { s = sprintf("%.17g", x); if (s !~ /[.e]/) s = s ".0"; return s }
    BEGIN {
        print "grid.origin=[" f(-3 * h) ", " f(-2 * h) "]"
        print "grid.cells=[" int(2000 / h + 0.5) + 6 ", " int(200 / h + 0.5) + 4 "]"
        print "grid.cell_size=[" f(h) ", " f(h) "]"
        print "bodies.[0].rectangle.min=[" f(-h) ", 0.0]"
        print "bodies.[0].rectangle.max=[" f(2000 + h) ", 200.0]"
        print "boundaries.[0].rectangle.min=[" f(-h) ", 0.0]"
        print "boundaries.[0].rectangle.max=[0.0, " f(h) "]"
        print "boundaries.[1].rectangle.min=[2000.0, 0.0]"
        print "boundaries.[1].rectangle.max=[" f(2000 + h) ", " f(h) "]"
        print "boundaries.[2].rectangle.min=[" f(1000 - h) ", " f(200 - h) "]"
        print "boundaries.[2].rectangle.max=[" f(1000 + h) ", 200.0]"
        if (grow == "grow") print "cracks.[0].points=([1000.0, " f(-h) "], [1000.0, 100.0])"
        else print "cracks.[0].points=([1000.0, " f(-h) "], [1000.0, 100.0], [1000.0, " f(200 + h) "])"
    }'
}

# one run: NAME H [OVERRIDE...]; its curve in $RUNS/NAME.dat and a row of
# the table in $RUNS/NAME.row; the grown crack's runs are named grow-*
run_case() {
    local name=$1 h=$2 scene=$SCENE kind=""
    shift 2
    case $name in grow-*) scene=$GROW kind=grow ;; esac
    local -a o
    mapfile -t o < <(ovh "$h" "$kind")
    echo "fig-petersson: $name (h = $(printf '%.4g' "$h") mm $*) ..."
    fig_run "$RUNS/$name" "$scene" "${o[@]}" "$@"
    [ "$rc" = 0 ] || { echo "fig-petersson: $name: $why" >&2; exit 1; }
    awk -F, -v v=0.005 -v ramp=20 -f figures/fig-petersson/curve.awk \
        "$RUNS/$name/history.csv" >"$RUNS/$name.dat"
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
        { e = $c["cohesive_dissipated"] + $c["cohesive_stored"] } END { print e }' \
        "$RUNS/$name/history.csv" >"$RUNS/$name.coh"
    awk -v name="$name" -v h="$h" -v steps="$steps" -v loop="$loop" \
        -v coh="$(cat "$RUNS/$name.coh")" -v v=0.005 -v ramp=20 \
        -f figures/fig-petersson/row.awk "$RUNS/$name.dat" >"$RUNS/$name.row"
    cat "$RUNS/$name.row"
}

names=()
for h in $SPACINGS; do
    name=h$(printf '%.4g' "$h")
    run_case "$name" "$h"
    names+=("$name")
done
run_case rho-half 20 "materials.[0].rho=1.2e-3"
run_case linear 20 'cracks.[0].cohesive.law="linear"'
grows=()
for h in $GROW_SPACINGS; do
    name=grow-h$(printf '%.4g' "$h")
    run_case "$name" "$h"
    grows+=("$name")
done
# the peak load over the three spacings of runs NAME...: the spread line
spread() {
    local what=$1
    shift
    for n in "$@"; do awk '{ print $9 }' "$RUNS/$n.row"; done | awk -v what="$what" '
        { v[NR] = $1; if (NR == 1 || $1 < lo) lo = $1; if (NR == 1 || $1 > hi) hi = $1 }
        END { printf "%s: peak load over the three spacings: %.1f, %.1f, %.1f N; spread (max - min) / min = %.2f %% (issue: 5 %% or less)\n",
              what, v[1], v[2], v[3], 100 * (hi - lo) / lo }'
}

{
    echo "Petersson's notched beam (make fig-petersson, $MPM): $SCENE, XEFG, a pre-inserted"
    echo "cohesive ligament (exponential softening, f_t = 3.33 MPa, G_f = 0.137 N/mm, penalty"
    echo "3000 MPa/mm), E = 30 GPa, nu = 0.18, plane stress, b = 50 mm; mid-span pushed down at"
    echo "0.005 mm/ms (ramp 20 ms) to 2 mm; damping 0.05 /ms; rho 2.4e-3 g/mm^3."
    echo "P = dW/d delta from history.csv (W = xefg_held_work).  Reference (Petersson's measured"
    echo "curve, as code_aster ssnp166a checks it): 774 N at 0.365 mm, 598 N at 0.607 mm."
    echo "work: area to 2 mm; tail: P_e (mean load over the last 0.05 mm) x 2 mm; total against"
    echo "G_f b (D - a0) = 685 N mm; cohesive: dissipated + stored at the end; KE/U: the largest"
    echo "kinetic over strain energy after 40 ms.  grow-*: $GROW, the crack grown from the"
    echo "notch by criterion = \"tip\" (segments of one spacing), the same beam and law."
    echo "CPU: $(fig_cpu), one run at a time."
    echo
    printf '%-10s %6s %7s %7s %8s %7s %8s %7s %7s %6s %7s %6s %7s %7s %7s %7s %7s\n' run h steps "loop s" \
        "P(.365)" "%" "P(.607)" "%" peak "at mm" area "P_e" work "%" cohes "%" "KE/U"
    for name in "${names[@]}" rho-half linear "${grows[@]}"; do cat "$RUNS/$name.row"; done
    echo
    spread "pre-inserted" "${names[@]}"
    spread "grown (criterion = \"tip\")" "${grows[@]}"
    awk -v a="$(awk '{ print $5 }' "$RUNS/${names[0]}.row")" -v b="$(awk '{ print $5 }' "$RUNS/rho-half.row")" \
        -v c="$(awk '{ print $7 }' "$RUNS/${names[0]}.row")" -v d="$(awk '{ print $7 }' "$RUNS/rho-half.row")" \
        -v e="$(awk '{ print $9 }' "$RUNS/${names[0]}.row")" -v f="$(awk '{ print $9 }' "$RUNS/rho-half.row")" 'BEGIN {
        printf "density halved (h = 20): P(0.365) %+.2f %%, P(0.607) %+.2f %%, peak %+.2f %%\n", 100 * (b / a - 1), 100 * (d / c - 1), 100 * (f / e - 1) }'
    echo "load average before the runs: $load0; after: $(fig_load)"
} >"$txt"
cat "$txt"
fig_need_gnuplot "$txt written, no plot"
gnuplot -e "d1='$RUNS/${names[0]}.dat'; d2='$RUNS/${names[1]}.dat'; d3='$RUNS/${names[2]}.dat'; dl='$RUNS/linear.dat'; g1='$RUNS/${grows[0]}.dat'; g3='$RUNS/${grows[2]}.dat'; h1='${grows[0]#grow-h}'; h3='${grows[2]#grow-h}'; out='$OUT/fig-petersson.png'" \
    figures/fig-petersson/plot.gp || exit 1
echo "fig-petersson: $OUT/fig-petersson.png, $txt"
