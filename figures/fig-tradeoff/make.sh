#!/usr/bin/env bash
# make fig-tradeoff: error against cost, so that a user can pick a setting.
# Cost is the time loop's own wall time (the "N steps in T s" of the
# program's last line: no set-up, no final output), one run at a time.
#
# (a) Beam impact, figures/fig6/beam_supports.cfg (contact between impactor,
#     beam and supports) by build/stage5/mpm, each scheme (usl musl usf
#     usavg) at cfl 0.1, 0.2, ... 1.0, run to TIME = 2 ms, not 6: contact
#     starts at 0.58 ms and the impactor turns (its y momentum up) at 1.98
#     ms (musl, cfl 0.5), so the loading half of the impact, where the
#     schemes gain or lose energy (fig5, fig6), is in, at a third of the
#     cost.  Error: max |E/E0 - 1|
#     over the run (E = history.csv's total).  A run that goes unstable
#     (exit status 3) is listed as "unstable at t" and left off the plot.
# (b) The DCB of figures/fig1/dcb_full.cfg (musl, cfl 0.5, damped to the
#     static state at 400 ms) on grids of about 2, 1.5 and 1 mm with the
#     tip mid-cell (dx = 100/N, N odd, as tests/3-crossing/scenes/tip_mid_*
#     set them; written into build/fig-tradeoff/dcb_N.cfg), 1 to 4 points
#     per cell, and 0.75 mm with 2 (0.5 mm with 1 went unstable at 167
#     ms).  Error: the crack opening at the load against a converged static
#     Q4 analysis of the same loads (dcb_opening.c: stage 2's scene_fig2.c
#     measure, tests/support/q4.c linked, refined and extrapolated as
#     chapter 3's fig-tip does; fig2's FEA is on the MPM's own grid).
#
# Writes build/figures/fig-tradeoff-beam.png, fig-tradeoff-dcb.png and
# fig-tradeoff.txt (every run and the two Pareto fronts: the settings that
# no other setting beats in both error and time); runs under
# build/fig-tradeoff/.  About 5 minutes on one core.
#
# Environment: MPM (default build/stage5/mpm), TIME (beam, ms; default 2),
# SCHEMES, CFLS, DCB_GRIDS ("N:dy:ppc,ppc ..."), FEA_H (coarsest FEA mesh,
# mm; default 1, so meshes 1, 0.5, 0.25; 0.5 moved the references of h=2
# ppc=2 and h=1 ppc=4 by 0.04 and 0.02 %); TRADEOFF_RUNS (the runs' folder), TRADEOFF_TXT
# (the table), PLOT=0 (no figures): tools/bench.sh runs a subset so.
. "$(dirname "$0")/../lib.sh"
TIME=${TIME:-2.0}
SCHEMES=${SCHEMES:-"usl musl usf usavg"}
CFLS=${CFLS:-"0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1.0"}
DCB_GRIDS=${DCB_GRIDS:-"51:2:1,2,3,4 67:1.5:1,2,3,4 101:1:1,2,3,4 133:0.75:2"}
FEA_H=${FEA_H:-1}
RUNS=${TRADEOFF_RUNS:-build/fig-tradeoff}
txt=${TRADEOFF_TXT:-$OUT/fig-tradeoff.txt}
FEA=$RUNS/dcb_opening
mkdir -p "$RUNS"
load0=$(fig_load)

fig_mpm 5
# the FEA links the stage's library and the tests' Q4 solver
bash figures/fig-tradeoff/dcb_opening.sh 5 "$FEA" || exit 1

# pareto < label,group,time,error -> the front, by time
pareto() {
    sort -t, -k3,3g -k4,4g | awk -F, 'NR == 1 || $4 < best { print; best = $4 }'
}

# ---- (a) beam impact --------------------------------------------------------
beam=$RUNS/beam.csv
: >"$beam"
rows=() unstable=()
n=0 total=$(( $(wc -w <<<"$SCHEMES") * $(wc -w <<<"$CFLS") ))
g=0
for s in $SCHEMES; do
    g=$((g + 1))
    for c in $CFLS; do
        n=$((n + 1))
        dir=$RUNS/beam-$s-$c
        fig_run "$dir" figures/fig6/beam_supports.cfg run.snapshots=0 run.update="$s" \
            run.cfl="$c" run.time="$TIME"
        if [ "$rc" = 0 ]; then
            err=$(awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
                NR == 2 { e0 = $c["total"] }
                { d = $c["total"] / e0 - 1; if (d < 0) d = -d; if (d > m) m = d }
                END { printf "%.4e", m }' "$dir/history.csv")
            echo "$s $c,$g,$loop,$err" >>"$beam"
            rows+=("$(printf '%-6s %4s %7s %8s %10s  %s' "$s" "$c" "$steps" "$loop" "$err" \
                "$(awk -v e="$err" 'BEGIN { if (e >= 1) print "E off by over 100 %: blew up, not stopped" }')")")
            echo "fig-tradeoff: beam $n/$total: $s cfl $c: error $err, loop $loop s"
        else
            rows+=("$(printf '%-6s %4s %7s %8s %10s  %s' "$s" "$c" - - - "$why")")
            unstable+=("$s $c")
            echo "fig-tradeoff: beam $n/$total: $s cfl $c: $why"
        fi
    done
done
pareto <"$beam" >"$RUNS/beam-front.csv"

# ---- (b) DCB ------------------------------------------------------------------
# dcb_scene N DY: dcb_full.cfg on a grid of dx = 100/N, dy, 4 mm margins,
# the tip mid-cell (figures/fig-tradeoff/dcb_scene.sh, shared with
# make fig-xefg-dcb)
dcb_scene() { bash figures/fig-tradeoff/dcb_scene.sh "$1" "$2"; }

dcb=$RUNS/dcb.csv
: >"$dcb"
drows=() dunstable=()
n=0 total=0
for spec in $DCB_GRIDS; do
    IFS=: read -r N dy ppcs <<<"$spec"
    total=$((total + $(tr , ' ' <<<"$ppcs" | wc -w)))
done
for spec in $DCB_GRIDS; do
    IFS=: read -r N dy ppcs <<<"$spec"
    scene=$RUNS/dcb_$N.cfg
    dcb_scene "$N" "$dy" >"$scene"
    for p in ${ppcs//,/ }; do
        n=$((n + 1))
        dir=$RUNS/dcb-$N-$p
        fig_run "$dir" "$scene" run.snapshots=0 bodies.[0].points_per_cell="$p"
        if [ "$rc" != 0 ]; then
            drows+=("$(printf '%-5s %3s %9s  %s' "$dy" "$p" "100/$N" "$why")")
            echo "fig-tradeoff: dcb $n/$total: h=$dy ppc=$p: $why"
            dunstable+=("h=$dy ppc=$p")
            continue
        fi
        read -r pts x0 y0 om f0 f1 f2 order ref err < <("$FEA" "$scene" "$dir" "$FEA_H" \
            bodies.[0].points_per_cell="$p") || exit 1
        ae=$(awk -v e="$err" 'BEGIN { printf "%.4e", e < 0 ? -e : e }')
        echo "h=$dy ppc=$p,$p,$loop,$ae" >>"$dcb"
        drows+=("$(printf '%-5s %3s %9s %7s %6s %8s %8s %8s %+9.3f %5.2f' "$dy" "$p" "100/$N" \
            "$pts" "$steps" "$loop" "$om" "$(printf '%.5f' "$ref")" \
            "$(awk -v e="$err" 'BEGIN { print 100 * e }')" "$order")")
        echo "fig-tradeoff: dcb $n/$total: h=$dy ppc=$p: opening $om, FEA $ref, loop $loop s"
    done
done
pareto <"$dcb" >"$RUNS/dcb-front.csv"

# ---- table ---------------------------------------------------------------------
{
    echo "Error against cost (make fig-tradeoff, $MPM); loop s: the time loop's wall"
    echo "time as the program reports it, one run at a time, on: $(fig_cpu)"
    echo
    echo "(a) beam impact, figures/fig6/beam_supports.cfg to t = $TIME ms;"
    echo "    error = max |E/E0 - 1| over the run (E = total, 1000 rows)"
    printf '%-6s %4s %7s %8s %10s\n' scheme cfl steps "loop s" error
    printf '%s\n' "${rows[@]}" | sed "s/ *$//"
    echo "Pareto front (no run both faster and more accurate), by time:"
    awk -F, '{ printf "  %-12s %8s s  %s\n", $1, $3, $4 }' "$RUNS/beam-front.csv"
    echo
    echo "(b) DCB, figures/fig1/dcb_full.cfg (musl, cfl 0.5, 400 ms, damped);"
    echo "    h = dy (mm), dx = 100/N; opening: 2 x the y displacement of the upper"
    echo "    arm's loaded-end face point (as tests/2-fields/scene_fig2.c); FEA: Q4 of"
    echo "    the same loads, meshes $FEA_H, $(awk -v h="$FEA_H" 'BEGIN { print h / 2 ", " h / 4 }') mm, extrapolated with the order shown"
    printf '%-5s %3s %9s %7s %6s %8s %8s %8s %9s %5s\n' h ppc dx points steps "loop s" \
        "open mm" "FEA mm" "error %" order
    printf '%s\n' "${drows[@]}"
    echo "Pareto front, by time:"
    awk -F, '{ printf "  %-12s %8s s  %s\n", $1, $3, $4 }' "$RUNS/dcb-front.csv"
    echo
    echo "load average before the runs: $load0; after: $(fig_load)"
} >"$txt"
cat "$txt"
[ "${PLOT:-1}" = 0 ] && exit 0

# place_labels < label,group,time,error -> the same with a fifth column,
# the side of its point each label goes (0 right above, 1 right below,
# 2 left above, 3 left below): greedily, in order, the side whose box (in
# pixels of the plot, roughly) overlaps least the labels and points placed
place_labels() {
    awk -F, -v OFS=, -v cap=1 '
        { n++; L[n] = $1; G[n] = $2; T[n] = $3; E[n] = $4
          X[n] = log($3) / log(10); Y[n] = log($4 > cap ? cap : $4) / log(10)
          if (n == 1 || X[n] < x0) x0 = X[n]; if (n == 1 || X[n] > x1) x1 = X[n]
          if (n == 1 || Y[n] < y0) y0 = Y[n]; if (n == 1 || Y[n] > y1) y1 = Y[n] }
        function ov(a0, a1, b0, b1) { return a1 < b0 || b1 < a0 ? 0 : (a1 < b1 ? a1 : b1) - (a0 > b0 ? a0 : b0) }
        END {
            sx = 1250 / ((x1 - x0 + 1e-9) * 1.16); sy = 720 / ((y1 - y0 + 1e-9) * 1.2)
            for (i = 1; i <= n; i++) { px[i] = X[i] * sx; py[i] = Y[i] * sy
                nb++; b0[nb] = px[i] - 6; b1[nb] = px[i] + 6; c0[nb] = py[i] - 6; c1[nb] = py[i] + 6 }
            for (i = 1; i <= n; i++) {
                if (E[i] > cap) { print L[i], G[i], T[i], E[i], 0; continue }
                w = 7 * length(L[i]); best = -1
                for (q = 0; q < 4; q++) {
                    u0 = q < 2 ? px[i] + 8 : px[i] - 8 - w; u1 = u0 + w
                    v0 = q % 2 ? py[i] - 17 : py[i] + 2; v1 = v0 + 15
                    cost = 0
                    for (k = 1; k <= nb; k++) cost += ov(u0, u1, b0[k], b1[k]) * ov(v0, v1, c0[k], c1[k])
                    if (best < 0 || cost < best) { best = cost; bq = q; bu0 = u0; bu1 = u1; bv0 = v0; bv1 = v1 }
                }
                nb++; b0[nb] = bu0; b1[nb] = bu1; c0[nb] = bv0; c1[nb] = bv1
                print L[i], G[i], T[i], E[i], bq
            }
        }'
}
place_labels <"$beam" >"$RUNS/beam-labels.csv"
place_labels <"$dcb" >"$RUNS/dcb-labels.csv"

# the runs left off each plot, for its note: "usf 0.3 usf 0.4" -> "usf 0.3, 0.4"
left_off() {
    printf '%s\n' "$@" | awk '{ if ($1 != last) { printf "%s%s %s", (NR > 1 ? "; " : ""), $1, $2; last = $1 }
                                 else printf ", %s", $2 }'
}
bnote="triangles: error above 1, drawn at 1"
[ ${#unstable[@]} -gt 0 ] && bnote="left off, unstable at cfl: $(left_off "${unstable[@]}"); $bnote"
dnote="every run reached the static state"
[ ${#dunstable[@]} -gt 0 ] && dnote="left off, unstable: ${dunstable[*]}"

fig_need_gnuplot "$txt written, no plot"
gnuplot -e "data='$RUNS/beam-labels.csv'; front='$RUNS/beam-front.csv'; out='$OUT/fig-tradeoff-beam.png'; \
            names='$SCHEMES'; note='$bnote'; ylab='energy error, max |E/E0 - 1|'; \
            title='Beam impact to $TIME ms (stage 5, contact): energy error against cost, cfl 0.1 to 1'" \
    figures/fig-tradeoff/plot.gp || exit 1
gnuplot -e "data='$RUNS/dcb-labels.csv'; front='$RUNS/dcb-front.csv'; out='$OUT/fig-tradeoff-dcb.png'; \
            names='ppc=1 ppc=2 ppc=3 ppc=4'; note='$dnote'; ylab='|opening / converged FEA - 1|'; \
            title='DCB (musl, cfl 0.5): crack-opening error against cost, cell size h and points per cell'" \
    figures/fig-tradeoff/plot.gp || exit 1
echo "fig-tradeoff: $OUT/fig-tradeoff-beam.png, $OUT/fig-tradeoff-dcb.png, $txt"
