#!/usr/bin/env bash
# make tsan: the threaded tests under ThreadSanitizer.  Each argument is a
# tools/run_tests.sh group, "NAME:build/tsan/stageN/mpm:TEST ...": the
# solver and the test built with clang -fsanitize=thread and LLVM's OpenMP
# runtime (libomp).  The tests run the solver on 1 to 4 threads.
#
# Why clang and libomp, not GCC's libtsan with libgomp: TSan knows the
# order of two accesses only through code it instruments or calls it
# intercepts (pthread, atomics).  libgomp's barriers and thread pool are
# futexes and atomics in a library built without TSan, so a point's stress
# written in a parallel loop and read by the main thread after the loop's
# barrier is reported as a race; with GCC 12 the stage-1 disks on two
# threads give some 60 such reports, all in our loops, with
# OMP_WAIT_POLICY=passive too.  Silencing them would mean suppressing our
# own functions.  libomp instead calls an OMPT tool at every fork, join,
# barrier, task and lock, and LLVM's Archer (libarcher.so, shipped with
# libomp-14-dev and loaded by libomp when the program is built with TSan)
# passes those to TSan as happens-before edges.  What is left is libomp's
# own bookkeeping (a pthread mutex that one of its threads initialises and
# another locks), in the uninstrumented libomp: TSan's own message asks
# for ignore_noninstrumented_modules=1 for it, which ignores accesses made
# inside uninstrumented libraries (libomp, libconfig, libc) and nothing in
# ours.  No suppression file.
#
# The reports go to build/tsan/logs/race.PID (not to the output the tests
# compare); any report fails this script, and a run whose Archer did not
# load fails it too (without it every parallel loop would be unordered).
set -u
cd "$(dirname "$0")/.." || exit 1
root=$PWD
logs=$root/build/tsan/logs
rm -rf "$logs"
mkdir -p "$logs"
LLVM_LIB=${LLVM_LIB:-/usr/lib/llvm-14/lib}
export OMP_TOOL_LIBRARIES=$LLVM_LIB/libarcher.so
export TSAN_OPTIONS="ignore_noninstrumented_modules=1 halt_on_error=0 log_path=$logs/race"

# Archer present and active: its verbose line, from one solver of the list
first=${1#*:}
first=${first%%:*}
if ! ARCHER_OPTIONS=verbose=1 "$first" tests/1-mpm/scenes/disks.cfg -q -o build/tsan/archer \
        run.time=0.05 run.threads=2 2>&1 | grep -q 'Archer detected'; then
    echo "tsan: Archer ($OMP_TOOL_LIBRARIES) did not load in $first: the OpenMP" >&2
    echo "      barriers would be invisible to TSan (sh tools/deps.sh fuzz installs libomp-14-dev)" >&2
    exit 1
fi
rm -rf build/tsan/archer "${logs:?}"/*

t0=$(date +%s)
JOBS=${JOBS:-2} bash tools/run_tests.sh "$@"
rc=$?
t1=$(date +%s)
reports=$(cat "$logs"/race.* 2>/dev/null | grep -c '^WARNING: ThreadSanitizer')
if [ "$reports" -gt 0 ]; then
    echo "tsan: $reports ThreadSanitizer report(s), in $logs:"
    cat "$logs"/race.* | grep '^SUMMARY' | sort | uniq -c | sort -rn
    rc=1
else
    echo "tsan: no ThreadSanitizer report ($((t1 - t0)) s)"
fi
exit $rc
