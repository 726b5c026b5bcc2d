#!/usr/bin/env bash
# make fig6: the paper's Fig. 6, total energy against time for the four
# update schemes (USL, MUSL, USF, USAVG) in the beam impact of Fig. 5 with
# contact between the impactor, the beam and the supports
# (figures/fig6/beam_supports.cfg, stage 5, the scene's cfl 0.1, 0 to 6 ms).
#
# Writes build/figures/fig6.png (E/E0, the same zoomed, and the impactor's
# kinetic energy against time), build/figures/fig6_scene.png (the layout),
# build/figures/fig6.txt (per scheme: status, E/E0 at the end, its min,
# max and mean, the drift (max - min) / 2 / mean, contact start and leave,
# the wall time; and the steps of each curve), and the runs under
# build/figures/fig6/<scheme>/ (history.csv every step, curve.csv thinned).
# Contact start and leave as in figures/fig5/make.sh: the first step with
# material_contact_nodes > 0; the last such step when none follows and the
# impactor's y momentum is upward from then on. A run that goes unstable
# (exit status 3) is drawn up to where it stopped and marked; its numbers
# are over the rows before E/E0 leaves [0.5, 2]. About 1.5 minutes.
#
# Environment: MPM (default build/stage5/mpm), SCHEMES (default
# "usl musl usf usavg"), TIME (simulated ms, default the scene's 6).
. "$(dirname "$0")/../lib.sh"
SCHEMES=${SCHEMES:-"usl musl usf usavg"}
SCENE=figures/fig6/beam_supports.cfg
RUNS=$OUT/fig6
fig_mpm 5
mkdir -p "$RUNS"
over=(run.history_every=1)
[ -n "${TIME:-}" ] && over+=("run.time=$TIME")

# the layout at t = 0 (one tiny step)
"$MPM" "$SCENE" -q -o "$RUNS/layout" run.time=1e-9 >/dev/null || exit 1

# run SCHEME: one run into $RUNS/SCHEME; sets status, tfail and secs
run() {
    local s=$1
    echo "fig6: $s ..."
    fig_run "$RUNS/$s" "$SCENE" run.update="$s" "${over[@]}"
    tfail=$unstable_t
    status=${why:-ran}
    echo "fig6: $s: $status ($secs s)"
}

# measure SCHEME STATUS SECS: one line of the table, the thinned curve
# (time, E/E0, impactor KE / its initial) and the steps of E/E0
measure() {
    awk -F, -v s="$1" -v st="$2" -v secs="$3" -v curve="$RUNS/$1/curve.csv" \
        -v stepsf="$RUNS/$1/steps.txt" '
        NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k
                  print "time,energy,ke_impactor" > curve; next }
        NR == 2 { e0 = $c["total"]; k0 = $c["kinetic_impactor"]; start = -1; last = -1
                  mn = 1e30; mx = -1e30 }
        stop { next }
        {
            t = $c["time"]; e = $c["total"] / e0; k = $c["kinetic_impactor"] / k0
            if (e < 0.5 || e > 2) { stop = 1; next }   # blown up: not counted
            n++; tt[n] = t; ee[n] = e; sum += e
            if (e < mn) mn = e; if (e > mx) mx = e
            if ($c["material_contact_nodes"] > 0) { if (start < 0) start = t; last = t; up = 1 }
            else if (last >= 0 && $c["momentum_y_impactor"] <= 0) up = 0
            if ((n - 1) % 20 == 0) printf "%.6g,%.6g,%.6g\n", t, e, k > curve
            tend = t; eend = e; kend = k
        }
        END {
            printf "%.6g,%.6g,%.6g\n", tend, eend, kend > curve
            mean = sum / n
            left = (last >= 0 && last < tend && up && st == "ran")
            printf "%-5s %-24s %8.5f %8.5f %8.5f %8.5f %7.3f %7s %7s %7.4f %6.1f\n", s, st,
                eend, mn, mx, mean, 100 * (mx - mn) / 2 / mean,
                (start >= 0 ? sprintf("%.3f", start) : "-"),
                (left ? sprintf("%.3f", last) : "-"), kend, secs
            # steps: 0.1 ms windows in which E/E0 changes by more than 0.001
            j = 1; a = 0; out = ""
            for (i = 1; i <= n; i++) {
                while (j < n && tt[j] - tt[i] < 0.1) j++
                if (tt[j] - tt[i] < 0.1) break
                big = (ee[j] - ee[i] > 0.001 || ee[i] - ee[j] > 0.001)
                if (big && !a) { a = 1; ta = tt[i]; ea = ee[i] }
                if (big) { tb = tt[j]; eb = ee[j] }
                if (!big && a && tt[i] > tb) { a = 0; out = out sprintf("  %.2f-%.2f ms %+.4f", ta, tb, eb - ea) }
            }
            if (a) out = out sprintf("  %.2f-%.2f ms %+.4f", ta, tb, eb - ea)
            printf "%-5s%s\n", s, (out == "" ? "  none" : out) > stepsf
        }' "$RUNS/$1/history.csv"
}

start=$(fig_now)
rows=()
labels=""
for s in $SCHEMES; do
    run "$s"
    rows+=("$s|$status|$secs")
    [ -n "$tfail" ] && labels="$labels $s:$tfail"
done
wall=$(fig_since "$start")

summary=$OUT/fig6.txt
{
    echo "Fig. 6 (stage 5): $SCENE, cfl 0.1, frictionless contact (detected by"
    echo "the gap, the default) between beam and impactor and beam and supports."
    echo "E = kinetic + strain, E0 its initial value; min, max, mean of E/E0 over the"
    echo "run (an unstable run: over the rows before E/E0 left [0.5, 2]); drift % ="
    echo "(max - min) / 2 / mean (the paper: USAVG within +-0.18 % of its mean)."
    echo "start: first step with material_contact_nodes > 0; leave: the last such"
    echo "step, none after it and the impactor's y momentum upward after it (paper:"
    echo "about 0.4 and 4.2 ms). KEimp: impactor kinetic energy / initial at the end."
    printf '%-5s %-24s %8s %8s %8s %8s %7s %7s %7s %7s %6s\n' scheme status \
        "E/E0 end" min max mean "drift%" start leave KEimp "wall s"
    for r in "${rows[@]}"; do
        IFS='|' read -r s st secs <<<"$r"
        measure "$s" "$st" "$secs"
    done
    echo "Steps (0.1 ms windows in which E/E0 changes by more than 0.001, merged):"
    for r in "${rows[@]}"; do cat "$RUNS/${r%%|*}/steps.txt"; done
    echo "wall time of the runs: $wall s"
} >"$summary"
cat "$summary"

fig_need_gnuplot "runs and $summary written, no plot"
gnuplot -e "runs='$RUNS'; out='$OUT'; blowups='${labels# }'" figures/fig6/plot.gp || exit 1
echo "fig6: wrote $OUT/fig6.png, $OUT/fig6_scene.png and $summary"
