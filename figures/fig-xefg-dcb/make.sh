#!/usr/bin/env bash
# make fig-xefg-dcb: CRAMP (the MPM of stages 1-5, musl) and XEFG (stage 6,
# the meshfree method of the second paper, default xefg settings) side by
# side on one scene, the DCB of figures/fig1/dcb_full.cfg (damped to its
# static state at 400 ms), at three resolutions each, against the converged
# static Q4 FEA of stage 2.  Both run in build/stage6/mpm, on the same
# scenes: the method is the only override (run.method), so that both have
# the same material points (XEFG's nodes), loads, cfl 0.5 and damping.
#
# Grids: dx = 100/N, dy = h, 2 x 2 points per cell (the scene's), the tip
# mid-cell (N odd; figures/fig-tradeoff/dcb_scene.sh writes the scenes):
# h = 3, 2 and 1.2 mm by default.  The finest XEFG run (10,200 nodes) takes
# about two minutes; h = 1 would take three to four, times three crack
# lengths.
#
# For each method and grid, three runs: the crack tip at a0 = 50 mm and one
# cell either side, a0 - dx and a0 + dx (still mid-cell).  Measured:
#  (a) the crack-mouth opening at the load, the run at a0, against the
#      converged FEA (figures/fig-tradeoff/dcb_opening.c, as fig-tradeoff:
#      twice the y displacement of the upper arm's point nearest the loaded
#      end of the crack face; Q4 meshes 1, 0.5, 0.25 mm, extrapolated);
#  (b) the energy release rate from the compliance, G = P^2/(2B) dC/da with
#      C = Delta/P, dC/da by the central difference of the runs at a0 - dx
#      and a0 + dx.  Delta is the opening at the load line, the one that
#      does work with P (dcb_opening -g: the loads' f . u summed over the
#      loaded points, over P; it differs from the mouth opening of (a) by
#      about 0.1 %).  The FEA's G the same way, from its converged Delta at
#      the same two tips, so that both carry the same difference error;
#  (c) cost: the wall time of the time loop of the run at a0 (the "N steps
#      in T s" of the program's last line: no set-up, no output), one run at
#      a time.  G costs the three runs; the table gives their sum too.
# A run that goes unstable (exit status 3) is listed as "unstable at t"
# with its series and grid, which the plot then leaves off.
#
# Writes build/figures/fig-xefg-dcb.png (error against cost, log-log: the
# opening and G, one curve per method, points labelled with h) and
# build/figures/fig-xefg-dcb.txt (every number of the figure and more);
# runs under build/fig-xefg-dcb/.  About 10 minutes on a loaded machine,
# nine tenths of it XEFG.
#
# The load: the scene's 1 mN opens the mouth by about 3.2 mm, so that the
# points near the loaded end move more than a cell (1.6 mm each arm; cells
# of 3 to 1.2 mm).  CRAMP follows its points (updated positions; linear
# shape functions pay for each cell line crossed, chapter 1's scene_dcb),
# while the Q4 FEA and XEFG (total Lagrangian, small strain) solve the
# linear problem.  So the figure has a third series, CRAMP at a tenth of
# the load (mpm:0.1), where the points move a tenth as far: the errors are
# relative, so the FEA's are the same at any load, and XEFG's too (it is
# linear: its errors at 0.1 mN are those at 1 mN to the digits printed).
#
# Environment: MPM (default build/stage6/mpm), SERIES (default "mpm xefg
# mpm:0.1": the method, and after a colon each arm's load in mN when not
# the scene's 1), GRIDS ("N:h ...", default "35:3 51:2 85:1.2"), FEA_H
# (coarsest FEA mesh, mm; default 1), XDCB_RUNS (the runs' folder),
# XDCB_TXT (the table), PLOT=0 (no figure): tools/bench_xefg_dcb.sh runs a
# subset so.
. "$(dirname "$0")/../lib.sh"
SERIES=${SERIES:-"mpm xefg mpm:0.1"}
GRIDS=${GRIDS:-"35:3 51:2 85:1.2"}
FEA_H=${FEA_H:-1}
RUNS=${XDCB_RUNS:-build/fig-xefg-dcb}
txt=${XDCB_TXT:-$OUT/fig-xefg-dcb.txt}
FEA=$RUNS/dcb_opening
mkdir -p "$RUNS"
load0=$(fig_load)

fig_mpm 6
# the measure (fig-tradeoff's, with -g) links stage 6's library (XEFG's
# scenes load there) and the tests' Q4 solver
bash figures/fig-tradeoff/dcb_opening.sh 6 "$FEA" || exit 1

# the scenes: each grid with the tip at a0 - dx, a0, a0 + dx (K = -1, 0, 1)
for spec in $GRIDS; do
    IFS=: read -r N h <<<"$spec"
    for K in -1 0 1; do
        bash figures/fig-tradeoff/dcb_scene.sh "$N" "$h" "$K" >"$RUNS/dcb_${N}_$K.cfg"
    done
done

# results.csv, one row per series and grid:
#   series,method,load,h,N,points,steps,loop,loop3,open,open_fea,open_err,G,G_fea,G_err
# A series and grid one of whose three runs went unstable (exit status 3)
# has no row there: its line in the table says so, and the plot leaves it
# off (the runs after it on that grid are not made).
res=$RUNS/results.csv
echo "series,method,load,h,N,points,steps,loop,loop3,open,open_fea,open_err,G,G_fea,G_err" >"$res"
urows=()
n=0 total=$(( $(wc -w <<<"$SERIES") * $(wc -w <<<"$GRIDS") * 3 ))
for series in $SERIES; do
    IFS=: read -r m mN <<<"$series"
    # the load, when not the scene's: the same overrides for the runs and the FEA
    load=()
    if [ -n "$mN" ]; then
        f=$(awk -v l="$mN" 'BEGIN { printf "%.17g", l / 1000 }')
        load=("loads.[0].force=[0.0, $f]" "loads.[1].force=[0.0, -$f]")
    fi
    for spec in $GRIDS; do
        IFS=: read -r N h <<<"$spec"
        loop3=0 unst=""
        for K in -1 0 1; do
            n=$((n + 1))
            [ -n "$unst" ] && continue
            scene=$RUNS/dcb_${N}_$K.cfg
            dir=$RUNS/$m${mN:+-$mN}-$N-$K
            fig_run "$dir" "$scene" run.snapshots=0 run.method="$m" ${load[@]+"${load[@]}"}
            if [ "$rc" = 3 ]; then
                unst="$why, the tip at a0$(case $K in -1) echo " - dx" ;; 1) echo " + dx" ;; esac)"
                echo "fig-xefg-dcb: $n/$total: $series h=$h: $unst"
                urows+=("$(printf '%-6s %3s %4s %7s  %s' "$m" "${mN:-1}" "$h" "100/$N" "$unst")")
                continue
            fi
            loop3=$(awk -v a="$loop3" -v b="$loop" 'BEGIN { print a + b }')
            # pts x0 y0 open f0 f1 f2 order open_fea err tip P B delta d0 d1 d2 dorder delta_fea
            read -r pts x0 y0 om f0 f1 f2 order ref err tip P B dl dl0 dl1 dl2 dorder dref \
                < <("$FEA" -g "$scene" "$dir" "$FEA_H" ${load[@]+"${load[@]}"}) || exit 1
            echo "fig-xefg-dcb: $n/$total: $series h=$h tip $tip: opening $om (FEA $ref)," \
                 "load line $dl (FEA $dref), loop $loop s"
            case $K in
                -1) tipm=$tip dlm=$dl drefm=$dref ;;
                0)  pts0=$pts steps0=$steps loop0=$loop om0=$om ref0=$ref err0=$err ;;
                1)  # G = P^2/(2B) dC/da, C = Delta/P: P/(2B) dDelta/da
                    awk -v s="$series" -v m="$m" -v mN="${mN:-1}" -v h="$h" -v N="$N" -v pts="$pts0" -v steps="$steps0" \
                        -v loop="$loop0" -v loop3="$loop3" -v om="$om0" -v ref="$ref0" \
                        -v err="$err0" -v P="$P" -v B="$B" -v am="$tipm" -v ap="$tip" \
                        -v dm="$dlm" -v dp="$dl" -v fm="$drefm" -v fp="$dref" 'BEGIN {
                        G = P / (2 * B) * (dp - dm) / (ap - am)
                        Gf = P / (2 * B) * (fp - fm) / (ap - am)
                        printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%.6e,%.6e,%.6e\n", s, m, mN, h, N, pts,
                            steps, loop, loop3, om, ref, err, G, Gf, G / Gf - 1 }' >>"$res" ;;
            esac
        done
    done
done

# ---- table ---------------------------------------------------------------------
{
    echo "CRAMP (mpm) against XEFG on the DCB (make fig-xefg-dcb, $MPM):"
    echo "figures/fig1/dcb_full.cfg (musl, cfl 0.5, damped to 400 ms), 2 x 2 points"
    echo "per cell, dx = 100/N, dy = h (mm), the tip mid-cell; xefg: default settings"
    echo "(support 2, gauss 4, cohesive tip, m = 1).  FEA: Q4 of the same loads,"
    echo "meshes $FEA_H, $(awk -v h="$FEA_H" 'BEGIN { print h / 2 ", " h / 4 }') mm (columns put a node on the tip), extrapolated."
    echo "opening: the crack mouth at the load (mm), the run with a0 = 50 mm;"
    echo "G = P^2/(2B) dC/da (N/mm = mJ/mm^2), C = load-line opening / P, P = each"
    echo "arm's load (mN column; the scene's 1 mN, a tenth of it for the linear range),"
    echo "B = 1 mm, central difference over a0 -/+ dx (the FEA's the same way);"
    echo "loop s: the time loop of the run at a0 (the figure's cost); 3 runs: of all"
    echo "three (G's cost); rate: particle-steps/s of the run at a0.  CPU:"
    echo "$(fig_cpu), one run at a time."
    echo
    printf '%-6s %3s %4s %7s %6s %6s %8s %8s %9s %9s %8s %11s %11s %8s %9s\n' method mN h dx \
        points steps "loop s" "3 runs" "open mm" "FEA mm" "open %" "G" "G FEA" "G %" rate
    awk -F, 'NR > 1 { printf "%-6s %3s %4s %7s %6s %6s %8.3f %8.3f %9.5f %9.5f %+8.3f %11.5e %11.5e %+8.3f %9.3g\n",
        $2, $3, $4, "100/" $5, $6, $7, $8, $9, $10, $11, 100 * $12, $13, $14, 100 * $15, $6 * $7 / $8 }' "$res"
    [ ${#urows[@]} -gt 0 ] && printf '%s\n' "${urows[@]}"
    echo
    echo "load average before the runs: $load0; after: $(fig_load)"
} >"$txt"
cat "$txt"
[ "${PLOT:-1}" = 0 ] && exit 0

# plot.csv: the labels of the two panels (h and the signed error), loop s,
# |opening error|, |G error|; one block per series, in SERIES' order, two
# blank lines apart (gnuplot's index); a series with no row (every grid
# unstable) has no block and no curve
plotted=""
for series in $SERIES; do
    awk -F, -v s="$series" '$1 == s { n++ } END { exit !n }' "$res" || continue
    plotted="$plotted $series"
    awk -F, -v s="$series" '$1 == s { printf "h=%s (%+.3f %%),h=%s (%+.3f %%),%s,%.6e,%.6e\n",
        $4, 100 * $12, $4, 100 * $15, $8, $12 < 0 ? -$12 : $12, $15 < 0 ? -$15 : $15 }' "$res"
    printf '\n\n'
done >"$RUNS/plot.csv"
[ -n "$plotted" ] || { echo "fig-xefg-dcb: every run unstable, no plot; $txt written" >&2; exit 1; }
fig_need_gnuplot "$txt written, no plot"
gnuplot -e "data='$RUNS/plot.csv'; out='$OUT/fig-xefg-dcb.png'; series='${plotted# }'" \
    figures/fig-xefg-dcb/plot.gp || exit 1
echo "fig-xefg-dcb: $OUT/fig-xefg-dcb.png, $txt"
