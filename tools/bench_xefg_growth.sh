#!/usr/bin/env bash
# make bench: what a growing crack costs XEFG (stage 6, issue 27), on
# tests/6-xefg/scenes/kalthoff_coarse.cfg (6400 points; the cohesive crack
# grows by the hoop stress, about 35 segments from about 19 microseconds)
# run to XGROW_TIME ms, against the same scene with the crack stationary:
# the same cohesive crack without its growth group (a copy made here with
# sed: the scene reader cannot remove a key by an override), so that the
# only difference is growth.  This scene rather than growth_bar.cfg: its
# events are spread over the last three fifths of the run, at a size where
# the step's work, not the set-up, is the time, so that the cost counted is
# that of a crack while it grows; growth_bar.cfg grows 7 segments in its
# first quarter of a millisecond on about 200 points and then runs a grown
# crack for 0.77 ms more.
#
# Time, pair by pair (the program's own timing of its time loop; the median
# ratio): REPEAT pairs, each the stationary run then the growing one.  The
# growing run takes more steps (each event may lower the stable step, found
# again by power iteration, chapter 6b) and more work per step (the new
# parameters and Gauss points), so two ratios: of the loop times, and of
# the times per step.  Particle-steps per second of each: the points of the
# program's first line times the steps of its last ("N steps in T s") over
# T, the median over the pairs.  The growing run's events and power
# iterations after set-up: its "mpm: growth: crack 0 grew N ..." line.
# About 40 s a pair on one free core (30 s growing, 8 s stationary).
#
# tools/bench.sh calls it; `bash tools/bench_xefg_growth.sh` runs it alone.
# Environment: MPM (default build/stage6/mpm), REPEAT (pairs, default 3),
# XGROW_TIME (default 0.05), WORK (a folder for the runs; default a new
# one, removed at the end).
set -uf
cd "$(dirname "$0")/.." || exit 1
MPM=${MPM:-build/stage6/mpm}
REPEAT=${REPEAT:-3}
TIME=${XGROW_TIME:-0.05}
if [ -z "${WORK:-}" ]; then
    WORK=$(mktemp -d "${TMPDIR:-/tmp}/mpm-bench-xgrowth.XXXXXX")
    trap 'rm -rf "$WORK"' EXIT
fi
export OMP_NUM_THREADS=1
[ -x "$MPM" ] || { echo "bench: $MPM not built (run make stage6)" >&2; exit 1; }
SCENE=tests/6-xefg/scenes/kalthoff_coarse.cfg
# the scene with its crack stationary
sed -E 's/growth = \{[^}]*\}; *//' "$SCENE" >"$WORK/kalthoff_stationary.cfg"
grep -q 'growth *=' "$WORK/kalthoff_stationary.cfg" &&
    { echo "bench: $SCENE: growth group not removed" >&2; exit 1; }

# run SCENE NAME -> "points steps seconds" of its time loop (the output
# kept in $WORK/NAME.out), or "fail"
run() {
    $MPM "$1" -q -o "$WORK/run" run.time="$TIME" >"$WORK/$2.out" 2>"$WORK/$2.err" ||
        { echo fail; return; }
    local pts steps_s
    pts=$(head -1 "$WORK/$2.out" | sed -nE 's/.*: ([0-9]+) points,.*/\1/p')
    steps_s=$(sed -nE 's/.*\(([0-9]+) steps in ([0-9.]+) s.*/\1 \2/p' "$WORK/$2.out")
    if [ -z "$pts" ] || [ -z "$steps_s" ]; then echo fail; return; fi
    echo "$pts $steps_s"
}

median() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }

echo "stage 6: what a growing crack costs XEFG, $SCENE to $TIME ms"
echo "(one thread; stationary: the same cohesive crack without its growth group);"
printf 'time, growing / stationary, %s pairs (median of the pairs'"'"' ratios); load average before: %s\n' \
    "$REPEAT" "$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)"
rt=() rs=() ratet=() rateg=() events=""
for ((r = 0; r < REPEAT; r++)); do
    read -r pa na ta < <(run "$WORK/kalthoff_stationary.cfg" stationary)
    read -r pb nb tb < <(run "$SCENE" growing)
    if [ "$pa" = fail ] || [ "$pb" = fail ]; then
        echo "  pair $((r + 1)) failed: $(tail -1 "$WORK/stationary.err") $(tail -1 "$WORK/growing.err")"
        continue
    fi
    rt+=("$(awk -v a="$ta" -v b="$tb" 'BEGIN { printf "%.3f", b / a }')")
    rs+=("$(awk -v a="$ta" -v b="$tb" -v na="$na" -v nb="$nb" 'BEGIN { printf "%.3f", (b / nb) / (a / na) }')")
    ratet+=("$(awk -v p="$pa" -v n="$na" -v t="$ta" 'BEGIN { printf "%.4g", p * n / t }')")
    rateg+=("$(awk -v p="$pb" -v n="$nb" -v t="$tb" 'BEGIN { printf "%.4g", p * n / t }')")
    events=$(sed -nE 's/.*growth: crack 0 grew ([0-9]+) of .*\(([0-9]+) power iterations after set-up\).*/\1 \2/p' \
        "$WORK/growing.out")
done
[ ${#rt[@]} -gt 0 ] || { echo "  failed"; exit 1; }
printf '  %-36s %8s %7s %16s\n' run points steps "particle-steps/s"
printf '  %-36s %8s %7s %16.3g\n' "stationary crack" "$pa" "$na" "$(median "${ratet[@]}")" \
    "growing crack" "$pb" "$nb" "$(median "${rateg[@]}")"
read -r nev npow <<<"${events:-- -}"
printf '  growing run: %s growth events, the stable step found again %s times\n' "$nev" "$npow"
printf '  %-36s %6s  (%s)\n' "loop time, growing / stationary" "$(median "${rt[@]}")" "${rt[*]}" \
    "time per step, growing / stationary" "$(median "${rs[@]}")" "${rs[*]}"
printf 'load average after: %s\n' "$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)"
