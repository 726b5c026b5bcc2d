#!/usr/bin/env bash
# make fig5: the beam impact of the paper's Fig. 5 with contact between the
# beam and the impactor (stage 4, figures/fig5/beam_impact_contact.cfg):
# each update scheme, and the one-field MUSL run of figures/fig6 for
# comparison; the impactor's kinetic energy against time (the curve by
# which the paper times the impact, 0.4 to 4.2 ms) and the total energy.
#
# Writes build/figures/fig5.png, build/figures/fig5.txt (contact start and
# leave times per scheme, energies, the wall time) and the runs under
# build/figures/fig5/<run>/ (history.csv every step, curve.csv thinned).
# Contact starts at the first step with material_contact_nodes > 0; the
# impactor leaves at the last such step when none follows and its y
# momentum is upward from then on. For the one-field run, which has no
# contact columns, the start is the first step with strain energy (the
# first shared node), and it does not leave: the impactor's kinetic energy
# falls again after its peak.  USF runs at cfl 0.05 (it blows up in the
# bending beam at 0.1, see the scene's header); a run that goes unstable
# (exit status 3) is drawn up to where it stopped.  About 1.5 minutes on
# one core.
#
# Environment: MPM (default build/stage4/mpm), SCHEMES (default
# "usl musl usf"), USF_CFL (default 0.05), TIME (simulated ms, default 6).
. "$(dirname "$0")/../lib.sh"
SCHEMES=${SCHEMES:-"usl musl usf"}
USF_CFL=${USF_CFL:-0.05}
SCENE=figures/fig5/beam_impact_contact.cfg
ONE_FIELD=figures/fig6/beam_impact.cfg
RUNS=$OUT/fig5
fig_mpm 4
mkdir -p "$RUNS"
over=(run.history_every=1)
[ -n "${TIME:-}" ] && over+=("run.time=$TIME")

# run NAME SCENE SCHEME [overrides...]: one run into $RUNS/NAME; sets
# status and secs
run() {
    local name=$1 scene=$2 scheme=$3
    shift 3
    echo "fig5: $name ..."
    fig_run "$RUNS/$name" "$scene" run.update="$scheme" "${over[@]}" "$@"
    status=${why:-ran to the end}
    echo "fig5: $name: $status ($secs s)"
}

# measure NAME SCHEME CFL STATUS SECS: one line of the table, and the
# thinned curve (time, impactor KE / its start, E / E0, contact nodes)
measure() {
    awk -F, -v name="$1" -v scheme="$2" -v cfl="$3" -v st="$4" -v secs="$5" \
        -v curve="$RUNS/$1/curve.csv" -v timesf="$RUNS/$1/times.txt" '
        NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; contact = ("material_contact_nodes" in c)
                  print "time,ke_impactor,energy,contact_nodes" > curve; next }
        NR == 2 { e0 = $c["total"]; k0 = $c["kinetic_impactor"]; start = -1; last = -1; drift = 0 }
        {
            t = $2; e = $c["total"] / e0; k = $c["kinetic_impactor"] / k0
            d = e - 1; if (d < 0) d = -d; if (d > drift) drift = d
            n = contact ? $c["material_contact_nodes"] : ($c["strain"] > 1e-12 * e0)
            if (n > 0) { if (start < 0) start = t; last = t; up = 1; kleave = k }
            else if (last >= 0 && contact && $c["momentum_y_impactor"] <= 0) up = 0
            if (start >= 0 && (tmin == 0 || k < kmin)) { kmin = k; tmin = t; kpeak = 0 }
            else if (start >= 0 && k > kpeak) { kpeak = k; tpeak = t }
            if ((NR - 2) % 20 == 0) printf "%.6g,%.6g,%.6g,%d\n", t, k, e, n > curve
            tend = t; kend = k; eend = e
        }
        END {
            printf "%-14s %-5s %5s  %-20s", name, scheme, cfl, st
            printf " %7s", (start >= 0 ? sprintf("%.3f", start) : "-")
            if (contact && last >= 0 && last < tend && up && st == "ran to the end")
                printf " %7.3f %7.4f", last, kleave
            else printf " %7s %7s", (contact ? "-" : "held"), "-"
            if (st == "ran to the end") printf " %7.4f %8.4f %7.4f", kend, eend, drift
            else printf " %7s %8s %7s", "-", "-", "-"
            printf " %7.1f\n", secs
            left = (contact && last >= 0 && last < tend && up && st == "ran to the end")
            print (start >= 0 ? start : "-"), (left ? last : "-") > timesf
            if (!contact && kpeak > 0)
                printf "    (one field: impactor KE/K0 at its turn %.4f at %.3f ms, back to %.4f at %.3f ms, then %.4f at %.3f ms: held)\n", kmin, tmin, kpeak, tpeak, kend, tend
        }' "$RUNS/$1/history.csv"
}

start=$(fig_now)
rows=()
for s in $SCHEMES; do
    cfl=0.1
    [ "$s" = usf ] && cfl=$USF_CFL
    run "contact-$s" "$SCENE" "$s" run.cfl="$cfl"
    rows+=("contact-$s|$s|$cfl|$status|$secs")
done
run one-field-musl "$ONE_FIELD" musl
rows+=("one-field-musl|musl|0.1|$status|$secs")
wall=$(fig_since "$start")

summary=$OUT/fig5.txt
{
    echo "Fig. 5 with contact between bodies (stage 4): $SCENE, frictionless,"
    echo "V_sep 0.9, V_contact 1.1; one field for comparison: $ONE_FIELD."
    echo "start: first step in contact (one field: first shared node); leave: last"
    echo "contact step, none after it and the impactor's y momentum upward after it."
    echo "KE: impactor kinetic energy / its initial (at leaving, at the end); E/E0:"
    echo "total energy at the end; drift: max |E/E0 - 1| (- for a run that blew up)."
    printf '%-14s %-5s %5s  %-20s %7s %7s %7s %7s %8s %7s %7s\n' run scheme cfl status \
        start leave "KE@lv" "KE@end" "E/E0" drift "wall s"
    for r in "${rows[@]}"; do
        IFS='|' read -r name scheme cfl st secs <<<"$r"
        measure "$name" "$scheme" "$cfl" "$st" "$secs"
    done
    echo "wall time of the runs: $wall s"
} >"$summary"
cat "$summary"

fig_need_gnuplot "runs and $summary written, no plot"
# the blow-up times, for the key
labels=""
for s in $SCHEMES; do
    fig_unstable "$RUNS/contact-$s.log"
    [ -n "$unstable_t" ] && labels="$labels $s:$unstable_t"
done
gnuplot -e "runs='$RUNS'; out='$OUT'; blowups='${labels# }'; usfcfl='$USF_CFL'" \
    figures/fig5/plot.gp || exit 1
echo "fig5: wrote $OUT/fig5.png and $summary"
