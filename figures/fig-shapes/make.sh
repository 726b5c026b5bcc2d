#!/usr/bin/env bash
# make fig-shapes (issue 30): what the smooth shape functions buy, and what
# they cost.
#
# (a) The flying, vibrating bar of tests/8-shapes/scenes/bar_crossing.cfg:
#     the RMS displacement error over the mode's amplitude after 1.25
#     periods against the cell size, N = 8 ... 512 cells over the bar, for
#     linear, uGIMP and CPDI, and linear on the bar at rest (no point
#     crosses a cell).  The runs and the measure are the test's
#     (tests/8-shapes/scene_bar_crossing.c, MPM_BAR_CELLS set to the list).
# (b) The spinning disk of tests/1-mpm/scenes/spinning_disk.cfg (one turn,
#     12,695 steps, MUSL, the Jaumann rate): the largest von Mises stress
#     over rho v^2 after the turn (tests/support/spin.h's measure, from
#     particles_final.csv; physics: 0.41 at the centre, a sudden start
#     rings to about twice that) against the instructions per particle-step
#     of the same scene (tools/task1_cost.sh: callgrind, 30 steps less 10,
#     deterministic), for each shape with the paper's transfer and with
#     APIC, and uGIMP and CPDI with USL.  A run that stops is listed and
#     left off the plot.
# (c) fig-tradeoff's DCB (figures/fig1/dcb_full.cfg on its h = 2 mm grid,
#     figures/fig-tradeoff/dcb_scene.sh 51 2, 2 points per cell, musl, cfl
#     0.5, damped to the static state at 400 ms) and (d) fig-tradeoff's
#     beam impact (figures/fig6/beam_supports.cfg, musl, cfl 0.5, to 2 ms),
#     each with linear, uGIMP and CPDI: fig-tradeoff's errors (the opening
#     against the converged Q4 FEA, figures/fig-tradeoff/dcb_opening.c;
#     max |E/E0 - 1| over the run) against the instructions per
#     particle-step of the same run (tools/task1_cost.sh).  The linear runs
#     are fig-tradeoff's "h=2 ppc=2" and "musl 0.5" points.  A shape the
#     scene refuses (contact with uGIMP or CPDI is not done) is listed
#     with the solver's message and left off.
#
# Writes build/figures/fig-shapes.png and fig-shapes.txt; runs under
# build/fig-shapes/.  1.5 minutes of wall time on two cores at a load of
# about 1 (2026-11-28, after issue 29's stored stencils; 11 minutes at a
# load of 19 before them).
#
# Environment: MPM (default build/stage8/mpm), BAR_CELLS (default
# "8 16 32 64 128 256 512"), DISK_RUNS ("shape:transfer:update ..."),
# SHAPES (panels c and d; default "linear gimp cpdi").
. "$(dirname "$0")/../lib.sh"
set -o pipefail
BAR_CELLS=${BAR_CELLS:-"8 16 32 64 128 256 512"}
DISK_RUNS=${DISK_RUNS:-"linear:flip:musl gimp:flip:musl cpdi:flip:musl linear:apic:musl gimp:apic:musl cpdi:apic:musl gimp:flip:usl cpdi:flip:usl"}
TEST=build/stage8/tests/8-shapes/scene_bar_crossing
RUNS=build/fig-shapes
DISK=tests/1-mpm/scenes/spinning_disk.cfg
SHAPES=${SHAPES:-"linear gimp cpdi"}
BEAM=figures/fig6/beam_supports.cfg
txt=$OUT/fig-shapes.txt
mkdir -p "$RUNS"
fig_mpm 8
fig_build "$TEST"
export OMP_NUM_THREADS=1

# ---- (a) the bar ------------------------------------------------------------
echo "fig-shapes: the bar, N = $BAR_CELLS"
# the test fails (exit 1) when a bound fails over the list's two finest
# grids; the rows are what the figure needs, and the test says which
MPM_BIN=$MPM MPM_BAR_CELLS=$BAR_CELLS "$TEST" >"$RUNS/bar.log" 2>&1 || true
grep -q '  bar ' "$RUNS/bar.log" || { cat "$RUNS/bar.log" >&2; echo "fig-shapes: the bar gave no rows" >&2; exit 1; }
# bar.dat: one block per series (linear, gimp, cpdi flying, linear at rest):
# h (mm), RMS error / A
awk '/^  bar / { key = $2 " " $4; if (key != last && NR > 1 && last != "") print "\n"; last = key
                 for (k = 1; k <= NF; k++) { if ($k == "h") h = $(k + 1); if ($k == "RMS") e = $(k + 1) }
                 sub(",", "", e); print h, e }' "$RUNS/bar.log" >"$RUNS/bar.dat"

# ---- (b) the disk -----------------------------------------------------------
disk=$RUNS/disk.dat
: >"$disk"
rows=()
for r in $DISK_RUNS; do
    IFS=: read -r shape transfer update <<<"$r"
    over="run.shape=$shape run.transfer=$transfer run.update=$update"
    # shellcheck disable=SC2086 # over splits into its items
    fig_run "$RUNS/disk-$shape-$transfer-$update" "$DISK" run.precision=full run.threads=1 $over
    if [ "$rc" != 0 ]; then
        rows+=("$(printf '%-6s %-5s %-5s %10s  %s' "$shape" "$transfer" "$update" - "$why: $unstable_msg")")
        echo "fig-shapes: disk $shape $transfer $update: $why"
        continue
    fi
    # spin.h: von Mises over rho v^2, rho = 1e-3, v = 1.048 x 10 mm/ms;
    # the median is the sorted list's entry n/2 (from 0)
    read -r vmmed vmmax < <(awk -F, 'NR > 2 { a = $5; b = $6; c = $7
            print sqrt(a * a - a * b + b * b + 3 * c * c) / (1e-3 * 10.48 * 10.48) }' \
            "$RUNS/disk-$shape-$transfer-$update/particles_final.csv" | sort -g |
        awk '{ v[NR - 1] = $1 } END { printf "%.4f %.4f\n", v[int(NR / 2)], v[NR - 1] }')
    read -r pts ips _ < <(bash tools/task1_cost.sh "$MPM" "$DISK" '' "$over run.threads=1") || exit 1
    echo "$shape $transfer $update,$ips,$vmmax,$vmmed" >>"$disk"
    rows+=("$(printf '%-6s %-5s %-5s %10s %8.3f %8.3f %7s' "$shape" "$transfer" "$update" "$ips" "$vmmax" "$vmmed" "$loop")")
    echo "fig-shapes: disk $shape $transfer $update: $ips instructions per particle-step, largest von Mises $vmmax rho v^2"
done

# ---- (c) the DCB and (d) the beam: fig-tradeoff's errors --------------------
FEA=$RUNS/dcb_opening
bash figures/fig-tradeoff/dcb_opening.sh 8 "$FEA" || exit 1
bash figures/fig-tradeoff/dcb_scene.sh 51 2 >"$RUNS/dcb_51.cfg" || exit 1
# refused DIR: the solver's first message (a scene it refuses: exit 1)
refused() { grep -m 1 'mpm: ' "$1.log" | sed 's/^mpm: [^:]*: //'; }
dcbdat=$RUNS/dcb.dat beamdat=$RUNS/beam.dat
: >"$dcbdat"
: >"$beamdat"
crows=() drows=() beamoff=()
for shape in $SHAPES; do
    over="run.shape=$shape run.threads=1"
    # shellcheck disable=SC2086 # over splits into its items
    fig_try "$RUNS/dcb-$shape" "$RUNS/dcb_51.cfg" run.snapshots=0 $over
    if [ "$rc" = 0 ]; then
        # shellcheck disable=SC2086
        read -r pts _ _ om _ _ _ _ ref err < <("$FEA" "$RUNS/dcb_51.cfg" "$RUNS/dcb-$shape" 1 $over) || exit 1
        ae=$(awk -v e="$err" 'BEGIN { printf "%.4e", e < 0 ? -e : e }')
        read -r _ ips _ < <(bash tools/task1_cost.sh "$MPM" "$RUNS/dcb_51.cfg" '' "$over") || exit 1
        echo "$shape,$ips,$ae" >>"$dcbdat"
        crows+=("$(printf '%-6s %6s %6s %8s %9s %9s %10s %7s' "$shape" "$pts" "$steps" "$ips" "$om" \
            "$(printf '%.5f' "$ref")" "$ae" "$loop")")
        echo "fig-shapes: dcb $shape: opening $om, FEA $ref, error $ae, $ips instructions per particle-step"
    else
        [ "$rc" = 1 ] || [ "$rc" = 3 ] || fig_failed "$RUNS/dcb-$shape"
        crows+=("$(printf '%-6s  %s' "$shape" "${why:-refused: $(refused "$RUNS/dcb-$shape")}")")
        echo "fig-shapes: dcb $shape: ${why:-refused}"
    fi
    over="run.shape=$shape run.threads=1 run.update=musl run.cfl=0.5"
    # shellcheck disable=SC2086
    fig_try "$RUNS/beam-$shape" "$BEAM" run.snapshots=0 run.time=2.0 $over
    if [ "$rc" = 0 ]; then
        # fig-tradeoff's measure: max |E/E0 - 1| of history.csv's total
        err=$(awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
            NR == 2 { e0 = $c["total"] }
            { d = $c["total"] / e0 - 1; if (d < 0) d = -d; if (d > m) m = d }
            END { printf "%.4e", m }' "$RUNS/beam-$shape/history.csv")
        read -r pts ips _ < <(bash tools/task1_cost.sh "$MPM" "$BEAM" '' "$over") || exit 1
        echo "$shape,$ips,$err" >>"$beamdat"
        drows+=("$(printf '%-6s %6s %6s %8s %10s %7s' "$shape" "$pts" "$steps" "$ips" "$err" "$loop")")
        echo "fig-shapes: beam $shape: energy error $err, $ips instructions per particle-step"
    else
        [ "$rc" = 1 ] || [ "$rc" = 3 ] || fig_failed "$RUNS/beam-$shape"
        drows+=("$(printf '%-6s  %s' "$shape" "${why:-refused: $(refused "$RUNS/beam-$shape")}")")
        echo "fig-shapes: beam $shape: ${why:-refused}"
        beamoff+=("$shape: ${why:-refused (exit 1)}")
    fi
done

{
    echo "# make fig-shapes ($(date -u +%Y-%m-%d), $(fig_cpu), load $(fig_load))"
    echo "# (a) the flying bar (tests/8-shapes/scene_bar_crossing.c, MPM_BAR_CELLS=\"$BAR_CELLS\"):"
    echo "#     RMS displacement error over A after 1.25 periods, and the rate from the grid before"
    grep -E '^  (bar |rates|\(stopped)' "$RUNS/bar.log"
    echo "# (b) the spinning disk, one turn ($DISK, run.threads=1):"
    echo "#     instructions per particle-step (tools/task1_cost.sh), von Mises / rho v^2 after"
    echo "#     the turn (largest, median), the time loop (s, on this machine, shared)"
    printf '%-6s %-5s %-5s %10s %8s %8s %7s\n' shape trans. upd. instr/ps largest median loop_s
    printf '%s\n' "${rows[@]}"
    echo "# (c) fig-tradeoff's DCB, h = 2 mm, 2 points per cell (figures/fig-tradeoff/dcb_scene.sh 51 2,"
    echo "#     musl, cfl 0.5, 400 ms): the opening at the load against the converged Q4 FEA"
    echo "#     (figures/fig-tradeoff/dcb_opening.c, meshes 1, 0.5, 0.25 mm, extrapolated)"
    printf '%-6s %6s %6s %8s %9s %9s %10s %7s\n' shape points steps instr/ps "open mm" "FEA mm" \
        "|err|" loop_s
    printf '%s\n' "${crows[@]}"
    echo "# (d) fig-tradeoff's beam impact ($BEAM, musl, cfl 0.5, to 2 ms):"
    echo "#     max |E/E0 - 1| over the run"
    printf '%-6s %6s %6s %8s %10s %7s\n' shape points steps instr/ps "|E/E0-1|" loop_s
    printf '%s\n' "${drows[@]}"
} | tee "$txt"

fig_need_gnuplot "$txt written, no plot"
beamnote=${beamoff[*]:+left off: $(printf '%s; ' "${beamoff[@]}" | sed 's/; $//')}
gnuplot -e "bar='$RUNS/bar.dat'; disk='$disk'; dcb='$dcbdat'; beam='$beamdat'; beamnote='$beamnote'; \
            out='$OUT/fig-shapes.png'" \
    figures/fig-shapes/plot.gp || exit 1
echo "fig-shapes: wrote $OUT/fig-shapes.png and $txt"
