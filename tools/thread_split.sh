#!/usr/bin/env bash
# tools/thread_split.sh MPM SCENE [OVERRIDES] -> the instructions of one step
# on one thread, and on two threads each thread's share (callgrind with
# --separate-threads, the difference of runs of 25 and 5 steps, so set-up
# does not count), and the speed-up the counts allow: one thread's over the
# larger share. Deterministic; timing on a shared machine is not. OVERRIDES
# (one word, "key=value" items separated by spaces) go to both runs.
# THREADS=N (default 2) counts N threads instead (valgrind runs them one at
# a time, so 16 threads are counted on 2 cores): the first thread's share,
# the largest other one and the bound. Used by make bench
# (tools/bench_threads.sh) and quoted in the parallel appendix.
set -u
mpm=$1 scene=$2 extra=${3:-}
T=${THREADS:-2}
W=$(mktemp -d "${TMPDIR:-/tmp}/split.XXXXXX")
trap 'rm -rf "$W"' EXIT
# shellcheck disable=SC2086 # OVERRIDES splits into its items
dt=$("$mpm" "$scene" -q -o "$W/probe" run.time=1e-9 $extra |
     sed -nE 's/.*dt = ([0-9.eE+-]+) ms.*/\1/p')
[ -n "${dt:-}" ] || { echo "thread_split: cannot read $scene" >&2; exit 1; }
for n in 5 25; do
    time=$(awk -v n="$n" -v dt="$dt" 'BEGIN { printf "%.17g", (n - 0.5) * dt }')
    # shellcheck disable=SC2086
    OMP_WAIT_POLICY=passive valgrind --tool=callgrind --separate-threads=yes \
        --callgrind-out-file="$W/two.$n" "$mpm" "$scene" -q -o "$W/run" \
        run.time="$time" run.threads="$T" run.snapshots=0 $extra >/dev/null 2>&1 &&
    valgrind --tool=callgrind --callgrind-out-file="$W/one.$n" "$mpm" "$scene" \
        -q -o "$W/run" run.time="$time" run.threads=1 run.snapshots=0 $extra \
        >/dev/null 2>&1 || { echo "thread_split: $scene failed" >&2; exit 1; }
done
# a thread's instructions less the final points file (the first thread
# writes it), as tools/task1_cost.sh counts: writing it costs more when its
# numbers have more digits (after 25 steps than after 5), not a cost of the
# step (4.5 M of the cracked DCB's 62 M a step on one thread)
incl() { callgrind_annotate --inclusive=yes "$1" 2>/dev/null |
         awk -v f=":$2 " 'index($0, f) { gsub(",", "", $1); print $1; exit }'; }
tot() { local all final
        all=$(callgrind_annotate "$1" 2>/dev/null |
              sed -nE 's/^ *([0-9,]+) .*PROGRAM TOTALS.*/\1/p' | tr -d ,)
        final=$(incl "$1" output_points_final)
        echo $(( all - ${final:-0} )); }
[ -f "$W/two.5-02" ] || { echo "thread_split: no second thread ran" >&2; exit 1; }
if [ "$T" = 2 ]; then
    awk -v o5="$(tot "$W/one.5")" -v o25="$(tot "$W/one.25")" \
        -v a5="$(tot "$W/two.5-01")" -v a25="$(tot "$W/two.25-01")" \
        -v b5="$(tot "$W/two.5-02")" -v b25="$(tot "$W/two.25-02")" 'BEGIN {
        o = (o25 - o5) / 20; a = (a25 - a5) / 20; b = (b25 - b5) / 20
        printf "one thread %.2f M instructions a step; two threads: %.2f M and %.2f M; bound %.2f\n",
               o / 1e6, a / 1e6, b / 1e6, o / (a > b ? a : b) }'
    exit 0
fi
first=0 other=0
for f in "$W"/two.25-*; do
    i=${f##*-}
    d=$(( $(tot "$W/two.25-$i") - $(tot "$W/two.5-$i") ))
    if [ "$i" = 01 ]; then first=$d; elif [ "$d" -gt "$other" ]; then other=$d; fi
done
awk -v o5="$(tot "$W/one.5")" -v o25="$(tot "$W/one.25")" -v a="$first" -v b="$other" \
    -v t="$T" 'BEGIN {
    o = (o25 - o5) / 20; a /= 20; b /= 20
    printf "one thread %.2f M instructions a step; %d threads: the first %.2f M, the largest other %.2f M; bound %.2f\n",
           o / 1e6, t, a / 1e6, b / 1e6, o / (a > b ? a : b) }'
