#!/usr/bin/env bash
# Same numbers across a change: run every scene of the repository with every
# update scheme on the stage-1 and stage-2 (and later) solvers of two builds,
# and compare every output file byte for byte.
#
#   tools/same_numbers.sh BASE_REV            build BASE_REV (a git revision) in
#                                             build/base and compare it with the
#                                             solvers of this tree (make stageN)
#   tools/same_numbers.sh DIR_A DIR_B         compare two folders that hold
#                                             stageN/mpm already built
#
# Each run takes STEPS steps (default 60) with two snapshots; stdout is
# compared without its timing line, stderr whole (an unstable run's
# diagnostic must not change either). A scene the base refuses as bad input
# and this tree runs (a feature the base lacks) is reported as new. Prints
# one line per run and "N passed, N failed"; exits non-zero on any
# difference.
#
# IGNORE, a sed address regex without '|' (for example '^# t = [0-9]'), removes the
# lines it matches from every output file of both sides before the
# comparison: for a span over which a known line was added to a file (the
# grid CSVs' time line), so that the rest is still compared byte for byte.
# The summary line says so. FILES, a list of output file names (for
# example "history.csv particles_final.csv"), compares those alone (with
# stdout and stderr): for a span over which the snapshots' times moved.
set -u
cd "$(dirname "$0")/.."
STEPS=${STEPS:-60}
SCHEMES=${SCHEMES:-"usl musl usf"}
STAGES=${STAGES:-"1 2"}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/same-numbers.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

if [ $# -eq 1 ]; then
    rev=$1
    A=build/base/$(git rev-parse --short "$rev") || exit 1
    if [ ! -d "$A/src" ]; then
        mkdir -p "$A"
        git archive "$rev" | tar -x -C "$A" || exit 1
    fi
    for s in $STAGES; do
        [ -d "$A/src/$s-"* ] 2>/dev/null || continue
        make -s -C "$A" "build/stage$s/mpm" >/dev/null || exit 1
    done
    for s in $STAGES; do make -s "build/stage$s/mpm" >/dev/null || exit 1; done
    A=$A/build
    B=build
elif [ $# -eq 2 ]; then
    A=$1
    B=$2
else
    sed -n '2,25p' "$0"
    exit 2
fi

SCENES=$(git ls-files '*.cfg' | grep -v '/bad/' | grep -v '^tests/fuzz/' | grep -v '_200k')
passed=0
failed=0
new=0
for s in $STAGES; do
    [ -x "$A/stage$s/mpm" ] && [ -x "$B/stage$s/mpm" ] || continue
    for scene in $SCENES; do
        # dt from a run too short for one step (the refusal names the step;
        # a scene short enough to run prints it as "dt ="), then STEPS steps
        dt=$("$B/stage$s/mpm" "$scene" -q -o "$WORK/probe" run.time=1e-12 2>&1 |
             sed -nE 's/.*(dt = |over time steps of )([0-9.eE+-]+) .*/\2/p' | head -1)
        if [ -z "$dt" ]; then
            continue          # a scene this stage refuses (a crack in stage 1)
        fi
        t=$(awk -v n="$STEPS" -v dt="$dt" 'BEGIN { printf "%.17g", (n - 0.5) * dt }')
        for scheme in $SCHEMES; do
            for side in A B; do
                dir=${!side}
                out=$WORK/$side
                rm -rf "$out"
                mkdir -p "$out"
                "$dir/stage$s/mpm" "$scene" -q -o "$out/o" run.update="$scheme" \
                    run.time="$t" run.snapshots=2 >"$out/stdout" 2>"$out/stderr"
                echo "exit $?" >>"$out/stderr"
                sed -i -e '/particle-steps\/s/d' -e '/^mpm: energy /d' -e 's/, [0-9]* threads*$//' \
                    -e "s#$out#OUT#g" "$out/stdout" "$out/stderr"
                if [ -n "${FILES:-}" ]; then
                    for f in "$out"/o/*; do
                        [[ " $FILES " == *" ${f##*/} "* ]] || rm -rf "$f"
                    done
                fi
                if [ -n "${IGNORE:-}" ]; then
                    find "$out" -type f -exec sed -i "\\|${IGNORE}|d" {} +
                fi
            done
            if [ "$(tail -1 "$WORK/A/stderr")" = "exit 1" ] &&
               [ "$(tail -1 "$WORK/B/stderr")" = "exit 0" ]; then
                new=$((new + 1))   # input the base refuses: a feature it lacks
                printf '  new        stage%s %-36s %s (the base refuses: %s)\n' "$s" \
                    "$scene" "$scheme" "$(head -1 "$WORK/A/stderr")"
            elif diff -r "$WORK/A" "$WORK/B" >"$WORK/diff" 2>&1; then
                passed=$((passed + 1))
                printf '  same       stage%s %-36s %s (%s files)\n' "$s" "$scene" "$scheme" \
                    "$(find "$WORK/B" -type f | wc -l)"
            else
                failed=$((failed + 1))
                printf '  DIFFERENT  stage%s %-36s %s\n' "$s" "$scene" "$scheme"
                head -5 "$WORK/diff" | sed 's/^/      /'
            fi
        done
    done
done
[ -n "${IGNORE:-}" ] && echo "(lines matching '$IGNORE' left out of every file)"
[ -n "${FILES:-}" ] && echo "(of the outputs, $FILES alone compared)"
echo "$passed passed, $failed failed ($new runs of scenes the base refuses)"
[ $failed -eq 0 ] && [ $passed -gt 0 ]
