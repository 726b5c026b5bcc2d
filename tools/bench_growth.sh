#!/usr/bin/env bash
# make bench: what J and growth cost (stage 7), on the DCB of
# tests/7-fracture/scenes/dcb_j.cfg and dcb_growth.cfg, each against the
# same scene without its j_integral and growth keys (a copy made here with
# sed: the scene reader cannot remove a key by an override).
#
# Instructions per particle-step (callgrind through tools/task1_cost.sh,
# 30 minus 10 steps, musl; deterministic): dcb_j without J, with J every
# 10 steps (two evaluations in the 20 steps counted) and, derived from
# those two, every 100 (the cost of an evaluation over 100 steps: the
# 20-step window holds none); dcb_growth without J and growth, and with
# them (J every 5, growth tested at each; no event yet in the window).
# Time, pair by pair (the program's own timing of its time loop; the
# median ratio): REPEAT pairs of N-step runs of dcb_j, and GROW_PAIRS pairs
# of dcb_growth to GROW_TIME ms (420: the tip grows 16 times from 354 ms),
# so that the events count too.
#
# tools/bench.sh calls it; `bash tools/bench_growth.sh` runs it alone.
# Environment: MPM (default build/stage7/mpm), REPEAT (default 5), STEPSJ
# (N, default 300), GROW_PAIRS (default 2), GROW_TIME (default 420), WORK
# (a folder for the runs; default a new one, removed at the end).
set -uf
cd "$(dirname "$0")/.." || exit 1
MPM=${MPM:-build/stage7/mpm}
REPEAT=${REPEAT:-5}
N=${STEPSJ:-300}
GROW_PAIRS=${GROW_PAIRS:-2}
GROW_TIME=${GROW_TIME:-420}
if [ -z "${WORK:-}" ]; then
    WORK=$(mktemp -d "${TMPDIR:-/tmp}/mpm-bench-growth.XXXXXX")
    trap 'rm -rf "$WORK"' EXIT
fi
export OMP_NUM_THREADS=1
[ -x "$MPM" ] || { echo "bench: $MPM not built (run make stage7)" >&2; exit 1; }
S=tests/7-fracture/scenes
# the scenes without their stage-7 keys
for f in dcb_j dcb_growth; do
    sed -E -e 's/j_integral = \{[^}]*\}; *//' -e 's/growth = \{[^}]*\}; *//' \
        "$S/$f.cfg" >"$WORK/${f}_plain.cfg"
done

# secs SCENE [overrides] -> seconds of N steps (or of GROW_TIME ms, with
# TO_END set) as the program times them
secs() {
    local scene=$1 dt time=$GROW_TIME
    shift
    dt=$($MPM "$scene" -q -o "$WORK/probe" run.time=1e-9 "$@" |
         sed -nE 's/.*dt = ([0-9.eE+-]+) ms.*/\1/p')
    [ -n "${TO_END:-}" ] ||
        time=$(awk -v n="$N" -v dt="$dt" 'BEGIN { printf "%.17g", (n - 0.5) * dt }')
    $MPM "$scene" -q -o "$WORK/run" run.update=musl run.time="$time" "$@" \
        >"$WORK/out" 2>"$WORK/err" || { echo fail; return; }
    sed -nE 's/.*steps in ([0-9.]+) s.*/\1/p' "$WORK/out"
}

# ratio A_SCENE A_OVERRIDES B_SCENE B_OVERRIDES -> "median list" of B / A
ratio() {
    local r a b ratios=()
    for ((r = 0; r < REPEAT; r++)); do
        # shellcheck disable=SC2086 # the overrides split into their items
        a=$(secs "$1" $2)
        # shellcheck disable=SC2086
        b=$(secs "$3" $4)
        [ "$a" = fail ] || [ "$b" = fail ] && continue
        ratios+=("$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.3f", b / a }')")
    done
    [ ${#ratios[@]} -gt 0 ] || { echo "- failed"; return; }
    echo "$(printf '%s\n' "${ratios[@]}" | sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }') ${ratios[*]}"
}

echo "stage 7: what J and growth cost, the DCB (tests/7-fracture/scenes), musl;"
echo "instructions per particle-step (callgrind, 30 minus 10 steps; deterministic)"
if command -v valgrind >/dev/null 2>&1; then
    cost() { bash tools/task1_cost.sh "$MPM" "$1" "" "${2:-}"; }
    read -r pts w0 _ < <(cost "$WORK/dcb_j_plain.cfg")
    read -r pts w10 _ < <(cost $S/dcb_j.cfg "cracks.[0].j_integral.every=10")
    w100=$(awk -v a="$w0" -v b="$w10" 'BEGIN { printf "%.0f", a + (b - a) / 10 }')
    read -r gpts g0 _ < <(cost "$WORK/dcb_growth_plain.cfg")
    read -r gpts g5 _ < <(cost $S/dcb_growth.cfg)
    printf '  %-46s %6s\n' "dcb_j ($pts points), no J" "$w0" \
        "dcb_j, J every 10 steps" "$w10" \
        "dcb_j, J every 100 steps (derived)" "$w100" \
        "dcb_growth ($gpts points), no J, no growth" "$g0" \
        "dcb_growth, J every 5, growth tested" "$g5"
    printf 'J every 10: %.3f x; every 100: %.3f x; one evaluation: %.0f instructions per point\n' \
        "$(awk -v a="$w0" -v b="$w10" 'BEGIN { print b / a }')" \
        "$(awk -v a="$w0" -v b="$w100" 'BEGIN { print b / a }')" \
        "$(awk -v a="$w0" -v b="$w10" 'BEGIN { print 10 * (b - a) }')"
    printf 'growth (J every 5, growth tested at each): %.3f x\n' \
        "$(awk -v a="$g0" -v b="$g5" 'BEGIN { print b / a }')"
fi
echo "time, with / without, pair by pair (median of the pairs' ratios):"
read -r med all < <(ratio "$WORK/dcb_j_plain.cfg" "" $S/dcb_j.cfg "cracks.[0].j_integral.every=10")
printf '  %-44s %6s  (%s)\n' "dcb_j, $N steps, J every 10 steps" "$med" "$all"
read -r med all < <(ratio "$WORK/dcb_j_plain.cfg" "" $S/dcb_j.cfg "cracks.[0].j_integral.every=100")
printf '  %-44s %6s  (%s)\n' "dcb_j, $N steps, J every 100 steps" "$med" "$all"
read -r med all < <(TO_END=1 REPEAT=$GROW_PAIRS ratio "$WORK/dcb_growth_plain.cfg" "" \
    $S/dcb_growth.cfg "")
printf '  %-44s %6s  (%s)\n' "dcb_growth to $GROW_TIME ms, J every 5, growing" "$med" "$all"
