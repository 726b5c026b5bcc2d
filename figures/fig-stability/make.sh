#!/usr/bin/env bash
# make fig-stability: a stability map of the four update schemes on the
# beam impact with contact between bodies (figures/fig6/beam_supports.cfg,
# stage 5): scheme x cfl factor (0.1 ... 1.0, and 1.2) x points per cell
# (1, 2x2, 3x3, 4x4, set on every body).
#
# Reduced run: 1.5 ms instead of 6. The impactor starts 1.3 mm above the
# beam at 2.43 m/s; contact begins near 0.58 ms (USAVG, 2 x 2), so 1.5 ms
# holds the free flight, where the impactor's rows of points cross node
# lines (USL's small nodal masses, eq. 20), and the first 0.9 ms of the
# impact, the beam pushed down; 6 ms would make the map take about half
# an hour on one core.
#
# Each run is one of:
#   stopped   exit status 3, "mpm: unstable at step N (t = X ms): particle P
#             QUANTITY = V" on stderr (the time, step, point, its body and
#             the quantity are recorded), or "...: QUANTITY = V" for a sum:
#             the energy guard (run.energy_limit, energy doubled);
#   drifting  ran to the end with max |E/E0 - 1| > BOUND (E = kinetic +
#             strain from history.csv, E0 its first row; default 1 %: five
#             times the +-0.18 % of the paper's USAVG curve over 6 ms, and
#             below the few per cent that MUSL and USF lose or gain on
#             Fig. 6);
#   stable    ran to the end within BOUND;
#   refused   the scene was refused (exit status 1) with a message: cfl
#             above 1 is, unless allow_cfl_above_one = true. Such a run is
#             then made again with it set ("insisted") and classified too.
# Every row of history.csv and of particles_final.csv (written by a run
# that ends; a stopped run keeps history.csv only) must be numbers, none
# nan or inf: a violation is printed as FINITE VIOLATION and makes the
# script fail after the figure is drawn.
#
# Writes build/figures/fig-stability.png, build/figures/fig-stability.txt
# and the runs under build/figures/fig-stability/<scheme>-c<cfl>-p<ppc>/.
# One run at a time; about 9 minutes on one core (560 s measured on a
# machine shared with other jobs).
#
# Environment: MPM (default build/stage5/mpm), SCHEMES (default
# "usl musl usf usavg"), CFLS (default "0.1 0.2 ... 1.0 1.2"), PPCS
# (default "1 2 3 4"), TIME (ms, default 1.5), BOUND (default 0.01).
. "$(dirname "$0")/../lib.sh"
SCHEMES=${SCHEMES:-"usl musl usf usavg"}
CFLS=${CFLS:-"0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1.0 1.2"}
PPCS=${PPCS:-"1 2 3 4"}
TIME=${TIME:-1.5}
BOUND=${BOUND:-0.01}
SCENE=figures/fig6/beam_supports.cfg
RUNS=$OUT/fig-stability
fig_mpm 5
rm -rf "$RUNS"
mkdir -p "$RUNS"

nbodies=$(grep -c 'points_per_cell' "$SCENE")
# ppc_over N: points_per_cell = N on every body
ppc_over() {
    local k
    for ((k = 0; k < nbodies; k++)); do echo "bodies.[$k].points_per_cell=$1"; done
}

# the layout per ppc: which body each point belongs to (column "body")
for n in $PPCS; do
    "$MPM" "$SCENE" -q -o "$RUNS/layout-p$n" run.time=1e-9 $(ppc_over "$n") \
        >/dev/null 2>&1 || { echo "fig-stability: layout ppc $n failed" >&2; exit 1; }
done
body_of() {  # body_of PPC POINT: the body's name
    local idx
    idx=$(awk -F, -v p="$2" 'NR == 2 { for (k = 1; k <= NF; k++) if ($k == "body") c = k }
                            NR == p + 3 { print $c }' "$RUNS/layout-p$1/particles_final.csv")
    awk -v i="$idx" '/^ *\{ *name *=/ { if (n++ == i) { sub(/.*name *= *"/, ""); sub(/".*/, ""); print } }' \
        <(sed -n '/^bodies/,/^);/p' "$SCENE")
}

# finite DIR: every data row of the run's csv files is numbers only (a
# snapshot's "# t = ..." line and the column names are not data); prints
# the offending file and line, returns 1 on a violation
finite() {
    local f bad=0
    for f in "$1"/*.csv; do
        [ -e "$f" ] || continue
        awk -F, '/^#/ { next } !named { named = 1; next } { for (k = 1; k <= NF; k++)
                     if ($k !~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/) {
                         printf "%s:%d: field %d is \"%s\"\n", FILENAME, NR, k, $k; exit 1 } }' "$f" \
            || bad=1
    done
    return $bad
}

# drift DIR: max |E/E0 - 1| over the rows of history.csv, and its time
drift() {
    awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
             NR == 2 { e0 = $c["total"] }
             { d = $c["total"] / e0 - 1; if (d < 0) d = -d; if (d > m) { m = d; tm = $c["time"] } }
             END { printf "%.6g %.4g\n", m, tm }' "$1/history.csv"
}

# run SCHEME CFL PPC [overrides]: one run; sets class, note (the cell's
# label) and line (the detail line)
violations=0
run() {
    local s=$1 c=$2 n=$3
    shift 3
    local name=$s-c$c-p$n$([ $# -gt 0 ] && echo -ins)
    local dir=$RUNS/$name d tm
    fig_try "$dir" "$SCENE" run.update="$s" run.cfl="$c" run.time="$TIME" $(ppc_over "$n") "$@"
    local fin=finite
    if [ -d "$dir" ] && ! finite "$dir" >"$dir.finite"; then
        fin="NOT-FINITE"
        violations=$((violations + 1))
        echo "fig-stability: FINITE VIOLATION in $name:" >&2
        cat "$dir.finite" >&2
    fi
    case $rc in
        0)
            read -r d tm < <(drift "$dir")
            if awk -v d="$d" -v b="$BOUND" 'BEGIN { exit !(d > b) }'; then
                class=drifting
            else
                class=stable
            fi
            note=$(awk -v d="$d" 'BEGIN { printf (100 * d < 100 ? "%.3g%%" : "%.0f%%"), 100 * d }')
            line=$(printf '%-5s %4s %3s  %-9s max|E/E0-1| %8.3g %% at %6.3f ms  %6s s  %s' \
                   "$s" "$c" "$n" "$class" "$(awk -v d="$d" 'BEGIN { print 100 * d }')" "$tm" "$secs" "$fin")
            ;;
        3)
            class=stopped
            local msg=$unstable_msg t=$unstable_t step p q v b
            step=$(sed -nE 's/.*unstable at step ([0-9]+) .*/\1/p' <<<"$msg")
            p=$(sed -nE 's/.*particle (-?[0-9]+) .*/\1/p' <<<"$msg")
            q=$(sed -nE 's/.*particle -?[0-9]+ (.*) = [^;]*; stopping.*/\1/p' <<<"$msg")
            v=$(sed -nE 's/.* = ([^;]*); stopping.*/\1/p' <<<"$msg")
            b=$( [ "$p" -ge 0 ] 2>/dev/null && body_of "$n" "$p" || echo "-")
            note=$(awk -v t="$t" 'BEGIN { printf "%.2g", t }')
            if [ -n "$p" ]; then
                line=$(printf '%-5s %4s %3s  %-9s at %.4g ms, step %s: particle %s (%s) %s = %s  %6s s  %s' \
                       "$s" "$c" "$n" "$class" "$t" "$step" "$p" "$b" "$q" "$v" "$secs" "$fin")
            else                          # a sum: the energy guard, an overflow
                q=$(sed -nE 's/.* ms\): (.*) = [^;]*; stopping.*/\1/p' <<<"$msg")
                line=$(printf '%-5s %4s %3s  %-9s at %.4g ms, step %s: %s = %s  %6s s  %s' \
                       "$s" "$c" "$n" "$class" "$t" "$step" "$q" "$v" "$secs" "$fin")
            fi
            ;;
        1)
            class=refused
            note=refused
            line=$(printf '%-5s %4s %3s  %-9s "%s"' "$s" "$c" "$n" "$class" \
                   "$(grep -m1 . "$dir.log")")
            ;;
        *)
            fig_failed "$dir"
            ;;
    esac
    echo "fig-stability: $line"
}

start=$(fig_now)
dat=$RUNS/map.dat
: >"$dat"
details=()
panel=0
for s in $SCHEMES; do
    panel=$((panel + 1))
    col=0
    for c in $CFLS; do
        col=$((col + 1))
        for n in $PPCS; do
            run "$s" "$c" "$n"
            details+=("$line")
            code=$(case $class in stable) echo 0 ;; drifting) echo 1 ;; stopped) echo 2 ;; *) echo 3 ;; esac)
            l1=$note l2=""
            eval "cell_${s}_${col}_${n}=\"\$class:\$note\""
            if [ "$class" = refused ]; then
                run "$s" "$c" "$n" run.allow_cfl_above_one=true
                details+=("  insisted: $line")
                l1=refused l2="$(sed 's/^stopped$/stop/; s/^drifting$/drift/; s/^stable$/ok/' <<<"$class") $note"
                eval "cell_${s}_${col}_${n}=\"refused:\$class \$note\""
            fi
            printf '%d %d %s %d %d "%s" "%s"\n' "$panel" "$col" "$c" "$n" "$code" "$l1" "$l2" >>"$dat"
        done
    done
    printf '\n\n' >>"$dat"
done
wall=$(fig_since "$start")

summary=$OUT/fig-stability.txt
{
    echo "Stability map, stage 5: $SCENE to $TIME ms (reduced from 6),"
    echo "points per cell set on every body; one run at a time."
    echo "stopped: exit 3 with 'unstable at step N (t = X ms): particle P QUANTITY'"
    echo "or the energy guard's 'energy ... = F' (F > 2: run.energy_limit)"
    echo "(cell: X ms); drifting: ran to the end with max |E/E0 - 1| > $BOUND; stable:"
    echo "within it (cell: max |E/E0 - 1|); refused: the scene refused (cfl > 1 without"
    echo "allow_cfl_above_one = true), then run with it set (cell: that outcome)."
    for s in $SCHEMES; do
        echo
        echo "$s (rows: points per cell n x n; columns: cfl)"
        printf '%-4s' ppc
        for c in $CFLS; do printf ' %-15s' "$c"; done
        echo
        for n in $(echo "$PPCS" | tr ' ' '\n' | sort -rn); do
            printf '%-4s' "$n"
            col=0
            for c in $CFLS; do
                col=$((col + 1))
                v=cell_${s}_${col}_${n}
                printf ' %-15s' "$(sed -E 's/^stopped:([^ ]*)/stop \1 ms/; s/^stable:/ok /; s/^drifting:/DRIFT /; s/^refused:stopped ([^ ]*)/ref>stop \1 ms/; s/^refused:stable/ref>ok/; s/^refused:drifting/ref>DRIFT/' <<<"${!v}")"
            done
            echo
        done
    done
    echo
    echo "Runs (scheme, cfl, ppc, outcome; the body named is the point's):"
    printf '%s\n' "${details[@]}"
    echo
    echo "history.csv / particles_final.csv rows with nan or inf: $violations run(s)"
    echo "wall time of the runs: $wall s"
} >"$summary"
cat "$summary"

fig_need_gnuplot "runs and $summary written, no plot"
gnuplot -e "data='$dat'; out='$OUT/fig-stability.png'; schemes='$SCHEMES'; cfls='$CFLS'; \
    ppcs='$PPCS'; bound='$BOUND'; tend='$TIME'" figures/fig-stability/plot.gp || exit 1
echo "fig-stability: wrote $OUT/fig-stability.png and $summary"
[ "$violations" -eq 0 ] || { echo "fig-stability: $violations run(s) wrote nan or inf" >&2; exit 1; }
