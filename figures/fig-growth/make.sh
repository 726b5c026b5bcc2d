#!/usr/bin/env bash
# make fig-growth: the same growing cracks by CRAMP (stage 7's J-integral
# growth, chapter 7b) and XEFG (stage 6's cohesive growth, chapter 6b),
# both run by build/stage7/mpm (run.method picks), side by side:
#
#  (a) the DCB of tests/7-fracture/scenes/dcb_growth.cfg, opened at its end
#      by an imposed displacement (4e-3 mm/ms each arm, ramped over 50 ms,
#      600 ms): the crack length a against the opening Delta, and the
#      opening at which a Q4 finite element analysis puts G(a) = G_c
#      (figures/fig-growth/dcb_fea.c: G = Delta^2 C'/(2 B C^2), the
#      compliance of tests/7-fracture/scene_growth_dcb.c);
#  (b) the DCB's crack paths;
#  (c) Kalthoff and Winkler's plate, the upper half
#      (tests/7-fracture/scenes/kalthoff_half.cfg for CRAMP,
#      figures/fig-growth/kalthoff_xefg.cfg for XEFG): the paths on the
#      plate with the experiment's line at 70 degrees, and each method's
#      first kink;
#  (e) the DCB's energy release rate at each event against the crack
#      length, G/G_c, G the FEA's G(a) at the event's opening (1 where a
#      run's events meet the FEA's G(a) = G_c; every resolution of both);
#  (d) error against cost on the DCB, for three resolutions per method
#      (figures/fig-growth/dcb_scene.sh writes the scenes), against the
#      time loop's wall time: the opening at the first event against the
#      FEA's for a = a0 = 50 mm, and the RMS over a = 54, 58, 62, 66 mm of
#      the opening at which the crack of that length grows (left off the
#      plot for a run whose path leaves the crack line by more than h: the
#      FEA is for the straight crack).
#
# XEFG's tips grow where the hoop stress of K_I, K_II at them is largest
# (direction = "hoop", chapter 6b).  Normal to sigma_1, the default, the
# DCB's crack turned by 90 degrees at its first event (the DCB's positive
# T-stress puts sigma_1 along the crack; chapter 7b, "CRAMP and XEFG,
# growing") and the plate's first kink was 42.6 degrees.  5.4 to 5.7 minutes of CPU time, 4.5 to
# 4.7 minutes on a shared two-core machine (6.3 when busier; the table
# prints the load averages and the time); the longest run, XEFG's plate with f_t = 1000
# MPa (86 events), takes most of it, and starts first.
#
# What makes the DCB comparison fair: the same beam, material, loading
# (the same end displacement against time, at the grid's node column x = 0
# for CRAMP and at the first column of points, x = h/2, for XEFG, which
# holds material at its points; each method's FEA curve puts the end
# there), damping, cfl and time; the same fracture energy (CRAMP's G_c
# = XEFG's G_f = 5e-5 N/mm).  The resolutions are each method's own
# (CRAMP: cells of about h with 2 x 2 points, points h/2 apart; XEFG: one
# node per cell of h, nodes h apart), and (d) compares them by what they
# cost.  Each method grows by its own rule: CRAMP by half a cell when J
# reaches G_c, XEFG by one node spacing when sigma_1 ahead of the tip
# reaches the cohesive law's f_t (XEFG_FT, the linear law), both in the
# direction of the largest hoop stress.
#
# The crack length: CRAMP's tip x (history.csv tipx_crack0_last, the tip
# moves with the material, as tests/7-fracture/scene_growth_dcb.c reads
# it); XEFG's 50 mm + segments x h (growth_segments; total Lagrangian, so
# the reference length; the path is straight or it is said).  The opening
# at which a crack of length a grows: the events' openings against the
# length before the event, interpolated to a.
#
# Writes build/figures/fig-growth.png and build/figures/fig-growth.txt;
# runs under build/fig-growth/, two at a time (the machine's cores;
# each run's cost is its own time loop, "N steps in T s").
#
# Environment: MPM (default build/stage7/mpm), MPM_H and XEFG_H (the
# resolutions h, mm; default "2 1.5 1" each), XEFG_FT (the DCB's f_t, MPa;
# default 1e-3), KX_FT (the Kalthoff plate's f_t values, MPa; default
# "2000 1000"), KX_TIME (the plate's time, ms; default its scene's 0.09:
# a shorter one for a quick look), JOBS (runs at a time, default 2),
# PLOT=0 (no figure),
# REUSE=1 (keep build/fig-growth and make only the runs it lacks: to
# redraw the figure and its table after a change to this script).
. "$(dirname "$0")/../lib.sh"
set -o pipefail
MPM_H=${MPM_H:-"2 1.5 1"}
XEFG_H=${XEFG_H:-"2 1.5 1"}
XEFG_FT=${XEFG_FT:-1e-3}
KX_FT=${KX_FT:-"2000 1000"}
KX_TIME=${KX_TIME:-0.09}
JOBS=${JOBS:-2}
RUNS=build/fig-growth
txt=$OUT/fig-growth.txt
[ "${REUSE:-0}" = 1 ] || rm -rf "$RUNS"
mkdir -p "$RUNS"
t_start=$(fig_now)
load0=$(fig_load)

fig_mpm 7
fig_build build/shared/tests/support/q4.o
FEA=$RUNS/dcb_fea
cc -std=c11 -Wall -Wextra -Werror -Wshadow -Wmissing-prototypes -Wundef \
    -D_POSIX_C_SOURCE=200809L -O2 -Itests/support figures/fig-growth/dcb_fea.c \
    build/shared/tests/support/q4.o -llapacke -lm -o "$FEA" || exit 1

# ---- the runs, JOBS at a time ----------------------------------------------
# fig_job NAME SCENE [OVERRIDE...]: runs $MPM in the background into
# $RUNS/NAME (fig_try), its status and times to $RUNS/NAME.rc
# the status of run NAME: sets rc, secs, loop, steps; a run that failed
# (not 0, not 3) stops the figure
result() {
    read -r rc secs loop steps <"$RUNS/$1.rc" || { echo "$FIG: $1: no result" >&2; exit 1; }
    case $rc in 0|3) ;; *) fig_failed "$RUNS/$1" ;; esac
}

for h in $MPM_H; do
    bash figures/fig-growth/dcb_scene.sh mpm "$h" >"$RUNS/dcb_mpm_$h.cfg"
done
for h in $XEFG_H; do
    bash figures/fig-growth/dcb_scene.sh xefg "$h" "$XEFG_FT" >"$RUNS/dcb_xefg_$h.cfg"
done
# the longest first (XEFG's grown plate, its finest DCB), so that the
# cores stay busy
for ft in $(printf '%s\n' $KX_FT | sort -g); do
    fig_job "kw-xefg-$ft" figures/fig-growth/kalthoff_xefg.cfg "cracks.[0].cohesive.f_t=$ft" \
        run.snapshots=18 "run.time=$KX_TIME"
done
for h in $(printf '%s\n' $XEFG_H | sort -g); do
    fig_job "dcb-xefg-$h" "$RUNS/dcb_xefg_$h.cfg" run.history_every=5
done
fig_job kw-mpm tests/7-fracture/scenes/kalthoff_half.cfg run.snapshots=18 "run.time=$KX_TIME"
for h in $MPM_H; do
    fig_job "dcb-mpm-$h" "$RUNS/dcb_mpm_$h.cfg" run.history_every=5
done
# the FEA: the end at x = 0 (CRAMP) and at h/2 (XEFG)
for xl in 0 $(for h in $XEFG_H; do awk -v h="$h" 'BEGIN { print h / 2 }'; done); do
    "$FEA" 0.1 0.33 5e-5 "$xl" 50 80 >"$RUNS/fea_$xl.txt" || exit 1
done
wait

# ---- the DCB: events, a against Delta, the error ----------------------------
# events_<run>.txt: one line per event, "t Delta a_before a_after"; the
# opening Delta(t) = 2 d(t), d the end's displacement (ramp of 50 ms to
# 4e-3 mm/ms); curve_<run>.txt: Delta a, a staircase for the plot
dcb_events() {    # RUN METHOD H
    awk -F, -v m="$2" -v h="$3" -v ev="$RUNS/events_$1.txt" -v cu="$RUNS/curve_$1.txt" '
        function open(t) { return 2 * (t <= 50 ? 4e-3 * t * t / 100 : 4e-3 * (t - 25)) }
        NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
        {   t = $(c["time"])
            if (m == "mpm") { n = $(c["events_crack0_last"]); a = $(c["tipx_crack0_last"]) }
            else { n = $(c["growth_segments"]); a = 50 + n * h }
            if (NR == 2) { printf "%.6g %.6g\n", open(t), a >cu; n0 = n; a0 = a; next }
            if (n != n0) {
                printf "%.6g %.6g\n%.6g %.6g\n", open(t), a0, open(t), a >cu
                printf "%.6g %.6g %.6g %.6g %d\n", t, open(t), a0, a, n - n0 >ev
            }
            n0 = n; a0 = a; tl = t }
        END { printf "%.6g %.6g\n", open(tl), a0 >cu }' "$RUNS/$1/history.csv"
    [ -f "$RUNS/events_$1.txt" ] || : >"$RUNS/events_$1.txt"
}
# the opening at which the crack of length A grows, interpolated between
# events (by a_before), against the FEA's: prints "A Delta Delta_FEA err",
# or "A - Delta_FEA -" where the run's events do not bracket A
AS="54 58 62 66"
dcb_error() {     # RUN FEA_TABLE
    awk -v as="$AS" 'FNR == NR { fea[$1 + 0] = $4; next }
        { n++; ab[n] = $3; d[n] = $2 }
        END { k = split(as, A, " ")
              for (j = 1; j <= k; j++) {
                  v = ""
                  for (i = 1; i < n; i++)
                      if (ab[i] <= A[j] && ab[i + 1] >= A[j] && ab[i + 1] > ab[i]) {
                          v = d[i] + (d[i + 1] - d[i]) * (A[j] - ab[i]) / (ab[i + 1] - ab[i]); break }
                  if (v == "") printf "%g - %.5f -\n", A[j], fea[A[j]]
                  else printf "%g %.5f %.5f %+.4f\n", A[j], v, fea[A[j]], v / fea[A[j]] - 1 } }' \
        "$2" "$RUNS/events_$1.txt"
}
# the last crack snapshot of a run (its grown path)
last_cracks() { ls "$RUNS/$1"/cracks_*.csv 2>/dev/null | tail -n 1; }
# largest |y - Y0| of the points past the first two, and the last point
path_stats() {    # CSV Y0: prints "maxdev xtip ytip npoints"
    awk -F, -v y0="$2" '/^[0-9]/ { n++; x = $3; y = $4; if (n > 2) { d = y - y0; if (d < 0) d = -d; if (d > m) m = d } }
        END { printf "%.3g %.4f %.4f %d\n", m + 0, x, y, n }' "$1"
}

# dcb.csv: method,h,points,steps,loop,events,a_end,maxdev,rms,maxerr,reached,
# init,init_fea,init_err (the opening at the first event, the FEA's at a0)
dcb=$RUNS/dcb.csv
echo "method,h,points,steps,loop,events,a_end,maxdev,rms,maxerr,reached,init,init_fea,init_err" >"$dcb"
errs=()
for spec in $(for h in $MPM_H; do echo "mpm:$h"; done) $(for h in $XEFG_H; do echo "xefg:$h"; done); do
    IFS=: read -r m h <<<"$spec"
    name=dcb-$m-$h
    result "$name"
    if [ "$rc" = 3 ]; then
        fig_unstable "$RUNS/$name.log"
        errs+=("$(printf '%-5s %4s  %s' "$m" "$h" "${why:-unstable}")")
        continue
    fi
    dcb_events "$name" "$m" "$h"
    xl=0
    [ "$m" = xefg ] && xl=$(awk -v h="$h" 'BEGIN { print h / 2 }')
    dcb_error "$name" "$RUNS/fea_$xl.txt" >"$RUNS/error_$name.txt"
    pts=$(sed -nE 's/.*: ([0-9]+) points, grid.*/\1/p' "$RUNS/$name.log" | head -n 1)
    read -r dev xt yt np < <(path_stats "$(last_cracks "$name")" 0)
    init=$(awk 'NR == 1 { print $2 }' "$RUNS/events_$name.txt")
    ifea=$(awk '$1 == 50 { print $4 }' "$RUNS/fea_$xl.txt")
    awk -v init="${init:--}" -v ifea="$ifea" -v m="$m" -v h="$h" -v pts="$pts" -v steps="$steps" -v loop="$loop" -v dev="$dev" \
        -v ev="$(wc -l <"$RUNS/events_$name.txt")" -v a="$(awk '{ a = $4 } END { print a + 0 }' "$RUNS/events_$name.txt")" '
        $2 != "-" { n++; s += $4 * $4; e = $4 < 0 ? -$4 : $4; if (e > mx) mx = e }
        END { printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%d,%s,%.5f,%s\n", m, h, pts, steps, loop, ev, a, dev,
                     n ? sprintf("%.5f", sqrt(s / n)) : "-", n ? sprintf("%.5f", mx) : "-", n,
                     init, ifea, init == "-" ? "-" : sprintf("%+.5f", init / ifea - 1) }' \
        "$RUNS/error_$name.txt" >>"$dcb"
done

# ---- Kalthoff-Winkler: first kink, events, path ---------------------------------
# kw.csv: run,method,f_t,steps,loop,events,t_first,kink,xtip,ytip,path,note
# (a run that went unstable: its steps and wall time (set-up included) to
# the stop, its path at the last snapshot, and "unstable at t")
kw=$RUNS/kw.csv
echo "run,method,f_t,steps,loop,events,t_first,kink,xtip,ytip,path,note" >"$kw"
for name in kw-mpm $(for ft in $KX_FT; do echo "kw-xefg-$ft"; done); do
    result "$name"
    m=mpm ft=-
    case $name in kw-xefg-*) m=xefg ft=${name#kw-xefg-} ;; esac
    note=""
    if [ "$rc" = 3 ]; then      # its outputs so far are kept, and listed
        fig_unstable "$RUNS/$name.log"
        note=${why:-unstable}
        steps=$(sed -nE 's/.*(unstable|stopped) at step ([0-9]+) .*/\2/p' "$RUNS/$name.log" | head -n 1)
        loop=$secs
    fi
    # the first event (t, microseconds) and the events at the end
    read -r n tf < <(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "events_crack0_last" || $i == "growth_segments") c = i; next }
        $c > 0 && tf == "" { tf = $2 * 1000 } { n = $c } END { print n + 0, (tf == "" ? "-" : sprintf("%.2f", tf)) }' \
        "$RUNS/$name/history.csv")
    # the first kink: the direction of the first new segment, from the
    # first snapshot that holds it (the points move with CRAMP's material)
    kink=-
    for f in "$RUNS/$name"/cracks_*.csv; do
        k=$(awk -F, '/^[0-9]/ { n++; x[n] = $3; y[n] = $4 }
            END { if (n > 2) printf "%.1f", atan2(y[3] - y[2], x[3] - x[2]) * 45 / atan2(1, 1) }' "$f")
        [ -n "$k" ] && { kink=$k; break; }
    done
    last=$(last_cracks "$name")
    awk -F, '/^[0-9]/ { print $3, $4 }' "$last" >"$RUNS/path_$name.txt"
    read -r dev xt yt np < <(path_stats "$last" 25)
    echo "$name,$m,$ft,$steps,$loop,$n,$tf,$kink,$xt,$yt,$RUNS/path_$name.txt,$note" >>"$kw"
done
# g_<run>.txt for (e): at each event of the DCB runs, "a_before G/G_c",
# G the FEA's energy release rate of the crack a_before at the event's
# opening: G = G_c (Delta / Delta_c(a))^2 (G grows as Delta^2 at a fixed
# length), Delta_c(a) the FEA's opening at G(a) = G_c, interpolated in a
for spec in $(for h in $MPM_H; do echo "mpm:$h"; done) $(for h in $XEFG_H; do echo "xefg:$h"; done); do
    IFS=: read -r m h <<<"$spec"
    xl=0
    [ "$m" = xefg ] && xl=$(awk -v h="$h" 'BEGIN { print h / 2 }')
    [ -f "$RUNS/events_dcb-$m-$h.txt" ] || continue
    awk 'FNR == NR { n++; fa[n] = $1; fd[n] = $4; next }
        { for (i = 1; i < n; i++)
              if (fa[i] <= $3 && fa[i + 1] >= $3) {
                  dc = fd[i] + (fd[i + 1] - fd[i]) * ($3 - fa[i]) / (fa[i + 1] - fa[i])
                  printf "%.6g %.6g\n", $3, ($2 / dc) ^ 2; break } }' \
        "$RUNS/fea_$xl.txt" "$RUNS/events_dcb-$m-$h.txt" >"$RUNS/g_dcb-$m-$h.txt"
done
# the DCB's paths for the plot: the finest run of each method
for spec in "mpm:${MPM_H##* }" "xefg:${XEFG_H##* }"; do
    IFS=: read -r m h <<<"$spec"
    last=$(last_cracks "dcb-$m-$h")
    [ -n "$last" ] && awk -F, '/^[0-9]/ { print $3, $4 }' "$last" >"$RUNS/path_dcb-$m.txt"
done

# ---- the table ----------------------------------------------------------------
{
    echo "CRAMP and XEFG on growing cracks (make fig-growth, $MPM)."
    echo
    echo "DCB: tests/7-fracture/scenes/dcb_growth.cfg (100 x 36 mm, a0 = 50 mm,"
    echo "E = 0.1 MPa, nu = 0.33, plane stress), its end opened to Delta(t), 600 ms."
    echo "CRAMP: J growth, G_c = 5e-5 N/mm, segments of half a cell, cells 100/N x h,"
    echo "2 x 2 points.  XEFG: cohesive growth, linear law, G_f = 5e-5 N/mm, direction = \"hoop\","
    echo "f_t = $XEFG_FT MPa (E G_f / f_t^2 = $(awk -v f="$XEFG_FT" 'BEGIN { printf "%.3g", 0.1 * 5e-5 / (f * f) }') mm; arm 18 mm), segments of h, nodes h"
    echo "apart.  FEA: Q4, 0.5 x 0.25 mm, G(a) = G_c at Delta = C sqrt(2 B G_c / C'),"
    echo "the end at x = 0 (CRAMP) or h/2 (XEFG).  Delta at which the crack of length a"
    echo "grows: the events' openings against the length before the event, interpolated."
    echo
    printf '%-5s %4s %6s %6s %8s %6s %7s %8s %7s\n' method h points steps "loop s" events "a end" "max|y|" "RMS %"
    tail -n +2 "$dcb" | while IFS=, read -r m h pts st lp ev a dev rms mx nr init ifea ierr; do
        printf '%-5s %4s %6s %6s %8.2f %6s %7.2f %8s' "$m" "$h" "$pts" "$st" "$lp" "$ev" "$a" "$dev"
        if [ "$rms" = - ]; then printf ' %7s' -; else awk -v r="$rms" 'BEGIN { printf " %7.2f", 100 * r }'; fi
        awk -v d="$dev" -v h="$h" 'BEGIN { if (d > h) printf "  path off"; printf "\n" }'
    done
    echo
    echo "The opening Delta (mm) at which the crack of length a grows: the FEA's (the end"
    echo "at x = 0), and each run's error against its FEA (%; a = 50: the first event):"
    echo
    printf '%-5s %4s' "" a
    for A in 50 $AS; do printf ' %9s' "$A mm"; done
    printf '\n%-5s %4s' FEA -
    for A in 50 $AS; do printf ' %9s' "$(awk -v A="$A" '$1 == A { printf "%.4f", $4 }' "$RUNS/fea_0.txt")"; done
    printf '\n'
    tail -n +2 "$dcb" | while IFS=, read -r m h pts st lp ev a dev rms mx nr init ifea ierr; do
        printf '%-5s %4s' "$m" "$h"
        if [ "$init" = - ]; then printf ' %9s' "no event"
        else awk -v e="$ierr" 'BEGIN { printf " %+8.2f%%", 100 * e }'; fi
        while read -r A v f e; do
            if [ "$v" = - ]; then printf ' %9s' "-"
            else awk -v e="$e" 'BEGIN { printf " %+8.2f%%", 100 * e }'; fi
        done <"$RUNS/error_dcb-$m-$h.txt"
        printf '\n'
    done
    echo "(XEFG's FEA has its end at h/2: $RUNS/fea_H/2.txt, fourth column;"
    echo "max|y|: the grown path's largest distance from the crack line, mm; \"path"
    echo "off\": more than h, so the straight crack's FEA does not apply to the row;"
    echo "RMS over a = $AS; -: not reached)"
    echo
    echo "G / G_c at the events whose crack length before them is 52 to 68 mm, G the FEA's"
    echo "G(a) at the event's opening, G_c (Delta / Delta_c(a))^2 (panel e):"
    echo
    printf '%-5s %4s %6s %7s %7s %7s\n' method h events min max mean
    for spec in $(for h in $MPM_H; do echo "mpm:$h"; done) $(for h in $XEFG_H; do echo "xefg:$h"; done); do
        IFS=: read -r m h <<<"$spec"
        awk -v m="$m" -v h="$h" '$1 >= 52 && $1 <= 68 { n++; s += $2; if (n == 1 || $2 < lo) lo = $2; if (n == 1 || $2 > hi) hi = $2 }
            END { if (n) printf "%-5s %4s %6d %7.3f %7.3f %7.3f\n", m, h, n, lo, hi, s / n
                  else printf "%-5s %4s %6d %7s %7s %7s\n", m, h, 0, "-", "-", "-" }' \
            "$RUNS/g_dcb-$m-$h.txt" 2>/dev/null || printf '%-5s %4s %6s\n' "$m" "$h" -
    done
    echo
    echo "Kalthoff-Winkler, the upper half, $(awk -v t="$KX_TIME" 'BEGIN { print t * 1000 }') us: CRAMP tests/7-fracture/scenes/"
    echo "kalthoff_half.cfg (G_c = 22.1 N/mm, cells of 1 mm, 2 x 2 points); XEFG"
    echo "figures/fig-growth/kalthoff_xefg.cfg (linear law, G_f = 22.1 N/mm, f_t as"
    echo "listed, nodes 1 mm apart, direction = \"hoop\").  Kink: the first new segment's angle to the notch,"
    echo "from the first snapshot that holds it (the experiment: about 70 degrees)."
    echo
    printf '%-5s %5s %5s %7s %6s %9s %5s  %s\n' method "f_t" steps "loop s" events "first us" kink "tip at the end (mm)"
    tail -n +2 "$kw" | while IFS=, read -r r m ft st lp ev tf k xt yt p note; do
        printf '%-5s %5s %5s %7.2f %6s %9s %5s  (%.2f, %.2f)%s\n' "$m" "$ft" "$st" "$lp" "$ev" "$tf" "$k" "$xt" "$yt" "${note:+  $note}"
    done
    [ ${#errs[@]} -gt 0 ] && { echo; printf '%s\n' "${errs[@]}"; }
    echo
    echo "CPU: $(fig_cpu); $JOBS runs at a time"
    echo "(loop s: each run's own time loop)."
    echo "load average before the runs: $load0; after: $(fig_load)"
    if [ "${REUSE:-0}" = 1 ]; then
        echo "(REUSE=1: runs kept from an earlier make; this one took $(fig_since "$t_start") s)"
    else
        echo "the figure's runs took $(fig_since "$t_start") s in all"
    fi
} >"$txt"
cat "$txt"
[ "${PLOT:-1}" = 0 ] && exit 0

# plot_cost.txt for (d): one block per method (index 0 CRAMP, 1 XEFG):
# loop s, |error at the first event|, RMS error at a = 54..66 ("-" when
# not reached, or when the path left the line by more than h), label
for m in mpm xefg; do
    awk -F, -v m="$m" 'NR > 1 && $1 == m && $12 != "-" {
        e = $14 < 0 ? -$14 : $14 + 0; r = ($9 == "-" || $8 > $2) ? "-" : $9
        printf "%s %s %s h=%s\n", $5, e, r, $2 }' "$dcb"
    printf '\n\n'
done >"$RUNS/plot_cost.txt"
fig_need_gnuplot "$txt written, no plot"
kx=""
for ft in $KX_FT; do kx="$kx $ft"; done
kkm=$(awk -F, '$1 == "kw-mpm" { print $8 }' "$kw")
kkx=$(for ft in $KX_FT; do awk -F, -v r="kw-xefg-$ft" '$1 == r { k = $8 } END { printf "%s ", k == "" ? "-" : k }' "$kw"; done)
gnuplot -e "runs='$RUNS'; out='$OUT/fig-growth.png'; kxt=$(awk -v t="$KX_TIME" 'BEGIN { print t * 1000 }'); hm='${MPM_H##* }'; hx='${XEFG_H##* }'; hms='$MPM_H'; hxs='$XEFG_H'; kx='${kx# }'; ft='$XEFG_FT'; kkm='${kkm:--}'; kkx='${kkx% }'" \
    figures/fig-growth/plot.gp || exit 1
echo "fig-growth: $OUT/fig-growth.png, $txt ($(fig_since "$t_start") s)"
