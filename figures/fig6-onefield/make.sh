#!/usr/bin/env bash
# make fig6-onefield: the beam impact of the paper's Fig. 5 and its total energy
# (Fig. 6) for USL, MUSL and USF with the stage-1 solver (one velocity field,
# so the impactor sticks to the beam once they share nodes).
#
# Writes build/figures/fig6_onefield.png (energy curves), build/figures/fig6_onefield_scene.png
# (the layout of Fig. 5), build/figures/fig6_onefield_summary.txt, and the runs under
# build/figures/fig6-onefield/<scheme>/; the summary also times the impactor's
# turn, and that of a MUSL run with it at 87 g (musl-87g/).  A scheme that goes
# unstable (exit status 3) is drawn up to where it stopped; the figure is still made.
#
# Environment: MPM (default build/stage1/mpm), SCHEMES (default
# "usl musl usf"), TIME (simulated ms, default the scene's 6).
. "$(dirname "$0")/../lib.sh"
SCHEMES=${SCHEMES:-"usl musl usf"}
SCENE=figures/fig6/beam_impact.cfg
RUNS=$OUT/fig6-onefield
mkdir -p "$RUNS"
fig_mpm 1
over=()
[ -n "${TIME:-}" ] && over+=("run.time=$TIME")

# the layout at t = 0 (one tiny step)
"$MPM" "$SCENE" -q -o "$RUNS/layout" run.time=1e-9 >/dev/null || exit 1

summary=$OUT/fig6_onefield_summary.txt
{
    echo "Fig. 6, stage 1 (one velocity field): total energy E = kinetic + strain,"
    echo "E0 = initial energy (impactor kinetic energy).  Scene $SCENE."
    printf '%-5s %-24s %8s %8s %8s %8s %8s %8s %8s %8s\n' scheme status \
        "E(1)/E0" "E(2)/E0" "E(3)/E0" "E(4)/E0" "E(5)/E0" "E(6)/E0" min max
} >"$summary"

for s in $SCHEMES; do
    dir=$RUNS/$s
    echo "fig6-onefield: $s ..."
    fig_run "$dir" "$SCENE" run.update="$s" ${over[@]+"${over[@]}"}
    status="ran to the end"
    [ "$rc" = 3 ] && status=${why/#unstable at /unstable at t = }   # "unstable at t = 1.2 ms"
    printf 'fig6-onefield: %s: %s (%.0f s)\n' "$s" "$status" "$secs"
    # E/E0 at whole milliseconds (last row at or before), and min/max over
    # the rows written before any blow-up (|E/E0 - 1| < 10)
    awk -F, -v s="$s" -v st="$status" '
        NR == 2 { e0 = $5; min = 1; max = 1 }
        NR > 1 {
            r = $5 / e0; tmax = $2
            if (r < 10 && r > -10) { if (r < min) min = r; if (r > max) max = r }
            for (k = 1; k <= 6; k++) if ($2 <= k + 1e-6) at[k] = r
        }
        END {
            printf "%-5s %-24s", s, st
            for (k = 1; k <= 6; k++)
                if (tmax >= k - 1e-3) printf " %8.4f", at[k]; else printf " %8s", "-"
            printf " %8.4f %8.4f\n", min, max
        }' "$dir/history.csv" >>"$summary"
done
{
    echo "Steps: 0.1 ms windows where E/E0 changes by more than 0.005 (merged):"
    for s in $SCHEMES; do
        awk -F, -v s="$s" '
            NR == 2 { e0 = $5 }
            NR > 1 { n++; t[n] = $2; e[n] = $5 / e0 }
            END {
                j = 1; a = 0
                for (i = 1; i <= n; i++) {
                    while (j < n && t[j] - t[i] < 0.1) j++
                    if (t[j] - t[i] < 0.1 || e[j] > 10 || e[j] < -10) break
                    big = (e[j] - e[i] > 0.005 || e[i] - e[j] > 0.005)
                    if (big && !a) { a = 1; t0 = t[i]; e1 = e[i] }
                    if (big) { t1 = t[j]; e2 = e[j] }
                    if (!big && a && t[i] > t1) { a = 0; out = out sprintf("  %.2f-%.2f ms: %+.4f", t0, t1, e2 - e1) }
                }
                if (a) out = out sprintf("  %.2f-%.2f ms: %+.4f", t0, t1, e2 - e1)
                printf "%-5s%s\n", s, (out == "" ? "  none" : out)
            }' "$RUNS/$s/history.csv"
    done
} >>"$summary"
# turn DIR: first shared node (the first step with strain energy), the
# impactor's turning point (its least kinetic energy / K0) and the peak it
# climbs back to before the shared nodes hold it again
turn() {
    awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
             NR == 2 { k0 = $c["kinetic_impactor"]; e0 = $c["total"]; kmin = 2 }
             { t = $c["time"]; k = $c["kinetic_impactor"] / k0
               if (k > 10) exit                          # blown up
               if (t0 == "" && $c["strain"] > 1e-12 * e0) t0 = t
               if (k < kmin) { kmin = k; tmin = t; kp = 0 } else if (k > kp) { kp = k; tp = t } }
             END { if (t0 == "") print "none"; else printf "%s %s %s %s %s\n", t0, tmin, kmin, tp, kp }' \
        "$1/history.csv"
}
# the same MUSL run with the impactor at 87 g (the other reading of the
# scan's "?87 g"): thickness 51.10 mm
m87=$RUNS/musl-87g
echo "fig6-onefield: musl, 87 g ..."
fig_try "$m87" "$SCENE" run.update=musl "bodies.[1].thickness=51.10" ${over[@]+"${over[@]}"}
[ "$rc" = 0 ] || fig_failed "$m87"
{
    echo "Impactor: first shared node, its turning point (least kinetic energy K/K0)"
    echo "and the peak it climbs back to:"
    for s in $SCHEMES musl-87g; do
        read -r t0 tmin kmin tp kp < <(turn "$RUNS/$s")
        if [ "$t0" = none ]; then
            printf '%-8s no shared node before it stopped\n' "$s"
        else
            printf '%-8s first shared node %.3f ms, turns at %.3f ms (K/K0 %.4f), back to %.4f at %.3f ms\n' \
                "$s" "$t0" "$tmin" "$kmin" "$kp" "$tp"
        fi
    done
    if [ -s "$RUNS/musl/history.csv" ]; then
        read -r a0 a1 _ < <(turn "$RUNS/musl")
        read -r b0 b1 _ < <(turn "$m87")
        awk -v a0="$a0" -v a1="$a1" -v b0="$b0" -v b1="$b1" 'BEGIN {
            printf "musl: first shared node to turning point %.3f ms at 187 g, %.3f ms at 87 g (%+.1f %%)\n",
                   a1 - a0, b1 - b0, 100 * ((b1 - b0) / (a1 - a0) - 1) }'
    fi
} >>"$summary"
cat "$summary"

# the blow-up times, for labels on the plot
labels=""
for s in $SCHEMES; do
    fig_unstable "$RUNS/$s.log"
    [ -n "$unstable_t" ] && labels="$labels $s:$unstable_t"
done

fig_need_gnuplot "runs and $summary written, no plot"
gnuplot -e "runs='$RUNS'; out='$OUT'; blowups='${labels# }'" figures/fig6-onefield/plot.gp || exit 1
echo "fig6-onefield: wrote $OUT/fig6_onefield.png, $OUT/fig6_onefield_scene.png and $summary"
