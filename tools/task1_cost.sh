#!/usr/bin/env bash
# tools/task1_cost.sh MPM SCENE [SEARCH [OVERRIDES]] -> "points whole task1": the
# instructions per particle-step of the whole step (every thread's, the
# history and snapshots included, the final points file not) and of Task 1 with
# cracks (cracks_key_fields() and all it calls), from callgrind runs of 30
# and 10 steps (their difference, so set-up does not count). Deterministic.
# SEARCH, when given, is set as run.crack_search; OVERRIDES (one word,
# "key=value" items separated by spaces) are passed on as they are. Used by
# make bench and make fig-crossing.
set -u
mpm=$1 scene=$2 search=${3:-} extra=${4:-}
W=$(mktemp -d "${TMPDIR:-/tmp}/task1.XXXXXX")
trap 'rm -rf "$W"' EXIT
# shellcheck disable=SC2086 # OVERRIDES splits into its items
read -r pts dt < <("$mpm" "$scene" -q -o "$W/probe" run.time=1e-9 $extra |
    sed -nE 's/.*: ([0-9]+) points.*dt = ([0-9.eE+-]+) ms.*/\1 \2/p')
[ -n "${pts:-}" ] || { echo "task1_cost: cannot read $scene" >&2; exit 1; }
for n in 10 30; do
    time=$(awk -v n="$n" -v dt="$dt" 'BEGIN { printf "%.17g", (n - 0.5) * dt }')
    valgrind --tool=callgrind --callgrind-out-file="$W/cg.$n" "$mpm" "$scene" -q \
        -o "$W/run" run.time="$time" ${search:+run.crack_search=$search} $extra \
        >/dev/null 2>"$W/err" || { echo "task1_cost: $scene failed" >&2; exit 1; }
done
# every thread's instructions less the final points file: writing that one
# file costs more when its numbers have more digits (after 30 steps than
# after 10), which is not a cost of the step (about 80 of ~1,000 on the DCB)
incl() { callgrind_annotate --inclusive=yes "$1" 2>/dev/null |
         awk -v f=":$2 " 'index($0, f) { gsub(",", "", $1); print $1; exit }'; }
total() { echo $(( $(callgrind_annotate "$1" 2>/dev/null |
                     sed -nE 's/^ *([0-9,]+) .*PROGRAM TOTALS.*/\1/p' | tr -d ,) -
                   $(incl "$1" output_points_final) )); }
task1() { callgrind_annotate --inclusive=yes "$1" 2>/dev/null |
          awk '/cracks_key_fields/ { gsub(",", "", $1); print $1; exit }'; }
a=$(total "$W/cg.10") b=$(total "$W/cg.30") ta=$(task1 "$W/cg.10") tb=$(task1 "$W/cg.30")
awk -v a="$a" -v b="$b" -v ta="${ta:-0}" -v tb="${tb:-0}" -v n="$pts" \
    'BEGIN { printf "%d %.0f %.1f\n", n, (b - a) / (20 * n), (tb - ta) / (20 * n) }'
