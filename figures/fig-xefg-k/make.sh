#!/usr/bin/env bash
# make fig-xefg-k: xefg.md Test 3, the LEFM edge crack (W x H = 10 x 20 mm,
# a/W = 0.45, plane strain, tension on the top and bottom rows), damped to
# rest and K_I taken by the interaction integral, at the full sizes W/20,
# W/40, W/80 (and W/10, the coarsest of make check), by the test that
# checks it (tests/6-xefg/scene_edge_crack.c, XEFG_K_SPACINGS): each run
# passes or fails as in make check.  Writes build/figures/fig-xefg-k.png
# (K_I / (sigma sqrt(pi a)) against h, with the handbook value and its 3 %
# band) and build/figures/fig-xefg-k.txt (the runs and the table).
#
# About a minute on one core, mostly W/80 (12800 points).
. "$(dirname "$0")/../lib.sh"
set -eo pipefail
TEST=build/stage6/tests/6-xefg/scene_edge_crack
RUNS=build/fig-xefg-k
fig_build "$TEST"
mkdir -p "$RUNS"
txt=$OUT/fig-xefg-k.txt
{
    echo "xefg.md Test 3 (make fig-xefg-k): $TEST, one run at a time, on:"
    echo "  $(fig_cpu)"
    for n in "10 20 40" "20 40 80"; do
        echo
        echo "== XEFG_K_SPACINGS=\"$n\""
        XEFG_K_SPACINGS=$n XEFG_K_TABLE="$RUNS/W${n// /-}.dat" "$TEST" | grep -v '^\['
    done
} | tee "$txt"
# one row per spacing (the two runs share W/20 and W/40, which come out the
# same), coarsest first; the limit of the three finest from the second run
dat=$RUNS/table.dat
{
    head -1 "$RUNS/W10-20-40.dat"
    cat "$RUNS/W10-20-40.dat" "$RUNS/W20-40-80.dat" | grep -v '^#' | sort -n -k1,1 -u
} >"$dat"
F=$(awk '!/^#/ { print $8; exit }' "$dat")
limit=$(sed -n 's/^# Aitken limit \([0-9.]*\).*/\1/p' "$RUNS/W20-40-80.dat")
{
    echo
    echo "Table (error against the handbook F = $F; Aitken limit of W/20, W/40, W/80: $limit):"
    cat "$dat"
} | tee -a "$txt"
note=$(awk '!/^#/ { k = $10 < 0 ? -$10 : $10; if (k > kmax) kmax = k; if ($6 > e) e = $6 }
    END { printf "|K_II / K_I| <= %.1e; every run static: KE/SE <= %.1e (and 15 / omega_1 settled)", kmax, e }' "$dat")
fig_need_gnuplot "$txt written, no plot"
gnuplot -e "data='$dat'; out='$OUT/fig-xefg-k.png'; F=$F; limit=$limit; note='$note'" figures/fig-xefg-k/plot.gp
echo "fig-xefg-k: $OUT/fig-xefg-k.png, $txt"
