#!/usr/bin/env bash
# make fig-kalthoff: Kalthoff and Winkler's plate by XEFG at four node
# spacings (issue 27; chapter 6b, "Kalthoff-Winkler"): the upper half
# plate, 100 x 100 mm, maraging steel (E = 190 GPa, nu = 0.3, rho = 8000
# kg/m^3, plane strain), struck at 16.5 m/s on the edge below the notch
# (50 mm long), 90 microseconds; the notch a cohesive crack (linear law,
# f_t = 1000 MPa, G_f = 22.1 N/mm) whose tip grows by the largest hoop
# stress of K_I, K_II (direction = "hoop"). The scenes:
#   h = 2.5   figures/fig-kalthoff/kalthoff_h2_5.cfg
#   h = 5/3   tests/6-xefg/scenes/kalthoff_h1_667.cfg
#   h = 1.25  tests/6-xefg/scenes/kalthoff_coarse.cfg
#   h = 1     figures/fig-growth/kalthoff_xefg.cfg with f_t = 1000 MPa
# each with run.time = KX_TIME and one snapshot (the path at the end).
#
# The numbers (build/figures/fig-kalthoff.txt), per spacing:
# - the first event's time (history.csv: the first row whose
#   growth_segments is not 0, the end of that step) and the first kink,
#   the first new segment's angle to the notch (cracks_00001.csv: XEFG's
#   crack is total Lagrangian, its points stay where they were made);
# - the crack speed: the path over a window of 4 segments (the outer
#   radius 4h of the ring that gives K) over the time between the events
#   that begin and end it, the largest over the run, against Rayleigh's
#   speed c_R = xi c_s, xi the root in (0.5, 1) of (2 - xi^2)^2 =
#   4 sqrt(1 - xi^2) sqrt(1 - kappa^2 xi^2), kappa^2 = (1 - 2 nu) / (2 (1 -
#   nu)), c_s = sqrt(E / (2 (1 + nu) rho)) (plane strain); beside it the
#   largest over 1 segment and the mean from the first event to the last;
# - growth away from the notch tip: points of the crack other than the
#   notch's two and its growth, or with x < 50 (the struck edge is x = 0);
# - the energy balance: in = the work of the held places (XEFG's account,
#   xefg_held_work) against kinetic + strain + cohesive stored +
#   dissipated; the error at the end (the log's "mpm: energy" line) and
#   the largest |error| over the run, both in % of in at the end.
# The spread of the first kinks over the spacings whose crack grew.
#
# Writes build/figures/fig-kalthoff.png and build/figures/fig-kalthoff.txt;
# runs under build/fig-kalthoff/, JOBS at a time, the finest first.
# Environment: MPM (default build/stage6/mpm), KX_TIME (ms, default 0.09),
# JOBS (default 2), PLOT=0 (no figure), REUSE=1 (keep the runs made).
. "$(dirname "$0")/../lib.sh"
set -o pipefail
KX_TIME=${KX_TIME:-0.09}
JOBS=${JOBS:-2}
RUNS=build/fig-kalthoff
txt=$OUT/fig-kalthoff.txt
[ "${REUSE:-0}" = 1 ] || rm -rf "$RUNS"
mkdir -p "$RUNS"
t_start=$(fig_now)
load0=$(fig_load)
fig_mpm 6

# the spacings: name, h (mm), scene, overrides
SPECS="h1:1:figures/fig-growth/kalthoff_xefg.cfg:cracks.[0].cohesive.f_t=1000
h1.25:1.25:tests/6-xefg/scenes/kalthoff_coarse.cfg:
h1.667:1.66667:tests/6-xefg/scenes/kalthoff_h1_667.cfg:
h2.5:2.5:figures/fig-kalthoff/kalthoff_h2_5.cfg:"

# fig_job NAME SCENE [OVERRIDE...]: $MPM in the background into $RUNS/NAME
while IFS=: read -r name h scene over; do
    fig_job "$name" "$scene" "run.time=$KX_TIME" run.snapshots=1 run.history_every=1 $over
done <<<"$SPECS"
wait

# Rayleigh's speed and the shear speed (m/s = mm/ms) of the steel
read -r cs cr < <(awk 'BEGIN { E = 190000; nu = 0.3; rho = 8e-3
    cs = sqrt(E / (2 * (1 + nu) * rho)); k2 = (1 - 2 * nu) / (2 * (1 - nu)); lo = 0.5; hi = 1
    for (i = 0; i < 100; i++) { x = (lo + hi) / 2; x2 = x * x
        f = (2 - x2) ^ 2 - 4 * sqrt(1 - x2) * sqrt(1 - k2 * x2); if (f < 0) lo = x; else hi = x }
    printf "%.6f %.6f\n", cs, cs * (lo + hi) / 2 }')

# per run: the events (k, t us, x, y, path s) and the energy error (t us, % of in at the end)
kw=$RUNS/kw.csv
echo "name,h,steps,loop,events,t_first,kink,vmax4,v1,vmean,xtip,ytip,chord,away,err_end,err_max" >"$kw"
while IFS=: read -r name h scene over; do
    read -r rc secs loop steps <"$RUNS/$name.rc" || { echo "$FIG: $name: no result" >&2; exit 1; }
    [ "$rc" = 0 ] || fig_failed "$RUNS/$name"
    last=$(ls "$RUNS/$name"/cracks_*.csv | tail -n 1)
    # the event times, one per segment (the history row of the step that added it)
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "growth_segments") c = i; next }
        $c > n { for (k = n + 1; k <= $c; k++) printf "%d %.6f\n", k, $2 * 1000; n = $c }' \
        "$RUNS/$name/history.csv" >"$RUNS/times_$name.txt"
    # the path: the crack's points, the notch's two first
    awk -F, '/^[0-9]/ { print $3, $4 }' "$last" >"$RUNS/path_$name.txt"
    # events: k, t (us), x, y, path length from the notch tip (mm)
    awk 'NR == FNR { t[$1] = $2; next }
         { n++; x[n] = $1; y[n] = $2 }
         END { s = 0; for (k = 3; k <= n; k++) { s += sqrt((x[k] - x[k - 1]) ^ 2 + (y[k] - y[k - 1]) ^ 2)
                   printf "%d %.6f %.6f %.6f %.6f\n", k - 2, t[k - 2], x[k], y[k], s } }' \
        "$RUNS/times_$name.txt" "$RUNS/path_$name.txt" >"$RUNS/events_$name.txt"
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
        { w = $(c["xefg_held_work"]); e = w - $(c["xefg_kinetic"]) - $(c["xefg_strain"])
          e -= $(c["cohesive_stored"]) + $(c["cohesive_dissipated"]); print $2 * 1000, e, w }' \
        "$RUNS/$name/history.csv" >"$RUNS/energy_$name.txt"
    # a fourth column: the error in % of in at the end
    awk 'NR == FNR { w = $3; next } { print $0, (w != 0 ? 100 * $2 / w : 0) }' \
        "$RUNS/energy_$name.txt" "$RUNS/energy_$name.txt" >"$RUNS/energy_$name.tmp" &&
        mv "$RUNS/energy_$name.tmp" "$RUNS/energy_$name.txt"
    err_end=$(sed -nE 's/^mpm: energy .*error [^ ]+ \(([^ ]+) % of in\).*/\1/p' "$RUNS/$name.log")
    err_max=$(awk '{ e = $2 < 0 ? -$2 : $2; if (e > m) m = e; w = $3 } END { printf "%.4f", 100 * m / w }' \
        "$RUNS/energy_$name.txt")
    away=$(awk -F, '/^[0-9]/ { n++; if ($1 != 0 || (n > 2 && $3 < 50)) a++ } END { print a + 0 }' "$last")
    awk -v name="$name" -v h="$h" -v st="$steps" -v lp="$loop" -v away="$away" \
        -v ee="$err_end" -v em="$err_max" '
        { n++; t[n] = $2; x[n] = $3; y[n] = $4; s[n] = $5 }
        END {
            kink = "-"; v4 = "-"; v1 = "-"; vm = "-"; xt = 50; yt = 25; ch = "-"; tf = "-"
            if (n > 0) {
                kink = sprintf("%.2f", atan2(y[1] - 25, x[1] - 50) * 45 / atan2(1, 1))
                tf = sprintf("%.2f", t[1]); xt = x[n]; yt = y[n]
                ch = sprintf("%.2f", atan2(yt - 25, xt - 50) * 45 / atan2(1, 1))
            }
            for (w = 1; w <= 4; w += 3) {
                m = 0; ok = 0
                for (k = 1; k + w <= n; k++) { dt = t[k + w] - t[k]; ok = 1
                    v = dt > 0 ? 1000 * (s[k + w] - s[k]) / dt : 1e30; if (v > m) m = v }
                if (ok) { if (w == 1) v1 = sprintf("%.0f", m); else v4 = sprintf("%.0f", m) }
            }
            if (n > 1 && t[n] > t[1]) vm = sprintf("%.0f", 1000 * (s[n] - s[1]) / (t[n] - t[1]))
            printf "%s,%s,%s,%s,%d,%s,%s,%s,%s,%s,%.3f,%.3f,%s,%s,%s,%s\n", name, h, st, lp, n, tf,
                   kink, v4, v1, vm, xt, yt, ch, away, ee, em }' "$RUNS/events_$name.txt" >>"$kw"
done <<<"$SPECS"

# ---- the table -------------------------------------------------------------
spread=$(awk -F, 'NR > 1 && $7 != "-" { if (lo == "" || $7 < lo) lo = $7; if (hi == "" || $7 > hi) hi = $7; n++ }
    END { if (n) printf "%.2f degrees over %d spacings (%.2f to %.2f)", hi - lo, n, lo, hi; else print "-" }' "$kw")
{
    echo "Kalthoff-Winkler by XEFG (make fig-kalthoff, $MPM), the upper half plate,"
    echo "$(awk -v t="$KX_TIME" 'BEGIN { print t * 1000 }') us: maraging steel E = 190 GPa, nu = 0.3, rho = 8000 kg/m^3, plane"
    echo "strain, struck at 16.5 m/s (ramped over 1 us) below the notch; the notch a"
    echo "cohesive crack, linear law, f_t = 1000 MPa, G_f = 22.1 N/mm, grown by segments"
    echo "of h in the direction of the largest hoop stress of K_I, K_II."
    echo "c_s = sqrt(E / (2 (1 + nu) rho)) = $(printf '%.0f' "$cs") m/s; Rayleigh (plane strain) c_R = $(printf '%.0f' "$cr") m/s"
    echo "= $(awk -v a="$cr" -v b="$cs" 'BEGIN { printf "%.4f", a / b }') c_s, the root of (2 - xi^2)^2 = 4 sqrt(1 - xi^2) sqrt(1 - kappa^2 xi^2),"
    echo "kappa^2 = (1 - 2 nu) / (2 (1 - nu))."
    echo
    printf '%-7s %6s %6s %7s %6s %8s %6s %16s %8s %7s %15s %6s %5s %8s %8s\n' h steps "loop s" events "first" kink \
        "v 4 seg" "(/ c_R)" "v 1 seg" "v mean" "tip at the end" chord away "err end" "max|err|"
    printf '%-7s %6s %6s %7s %6s %8s %6s %16s %8s %7s %15s %6s %5s %8s %8s\n' mm "" "" "" us deg "m/s" "" "m/s" "m/s" mm deg "" "%" "%"
    tail -n +2 "$kw" | while IFS=, read -r name h st lp n tf k v4 v1 vm xt yt ch aw ee em; do
        r=-
        [ "$v4" != - ] && r=$(awk -v v="$v4" -v c="$cr" 'BEGIN { printf "%.3f", v / c }')
        printf '%-7s %6s %6.1f %7s %6s %8s %6s %16s %8s %7s %15s %6s %5s %8s %8s\n' "$h" "$st" "$lp" "$n" "$tf" "$k" \
            "$v4" "($r)" "$v1" "$vm" "($xt, $yt)" "$ch" "$aw" "$ee" "$em"
    done
    echo
    echo "first: the first event's time (the end of its step); kink: the first segment's"
    echo "angle to the notch (experiment: about 70, issue 27: 60 to 72); v 4 seg: the"
    echo "largest crack speed over 4 segments (path over the time between the events that"
    echo "begin and end the window); v 1 seg: over one (a tip grows one segment per step"
    echo "at most: h / dt when two come in consecutive steps); v mean: first event to"
    echo "last; chord: the angle from the notch tip to the last tip; away: crack points"
    echo "not at the notch tip's growth (x < 50, or another crack; 0: no growth from"
    echo "the impact edge); err end: the energy balance's error at the end, max|err|: its"
    echo "largest |error| over the run, both in % of the work put in by the end (the held"
    echo "places' work, xefg_held_work)."
    echo "The spread of the first kinks: $spread."
    echo
    echo "CPU: $(fig_cpu); $JOBS runs at a time (loop s: each run's own time loop)."
    echo "load average before the runs: $load0; after: $(fig_load)"
    if [ "${REUSE:-0}" = 1 ]; then
        echo "(REUSE=1: runs kept from an earlier make; this one took $(fig_since "$t_start") s)"
    else
        echo "the figure's runs took $(fig_since "$t_start") s in all"
    fi
} >"$txt"
cat "$txt"
[ "${PLOT:-1}" = 0 ] && exit 0

fig_need_gnuplot "$txt written, no plot"
names=$(while IFS=: read -r name h scene over; do printf '%s ' "$name"; done <<<"$SPECS")
kinks=$(tail -n +2 "$kw" | cut -d, -f7 | tr '\n' ' ')
gnuplot -e "runs='$RUNS'; out='$OUT/fig-kalthoff.png'; kxt=$(awk -v t="$KX_TIME" 'BEGIN { print t * 1000 }'); names='${names% }'; kinks='${kinks% }'; cr=$cr" \
    figures/fig-kalthoff/plot.gp || exit 1
echo "fig-kalthoff: $OUT/fig-kalthoff.png, $txt ($(fig_since "$t_start") s)"
