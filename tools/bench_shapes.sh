#!/usr/bin/env bash
# make bench: what the shape functions cost (stage 8, issue 30): the
# instructions per particle-step of run.shape = "linear", "gimp" (uGIMP)
# and "cpdi" (CPDI1) on the 50k Sulsky disks of tools/bench/disks_50k.cfg
# (musl, one thread), callgrind through tools/task1_cost.sh (30 minus 10
# steps, deterministic), and each against linear.
#
# tools/bench.sh calls it; `bash tools/bench_shapes.sh` runs it alone
# (six callgrind runs: about 2 minutes of wall time on two shared cores,
# 2026-11-28, beside other runs).
# Environment: MPM (default build/stage8/mpm), SCENE (default
# tools/bench/disks_50k.cfg), SHAPES (default "linear gimp cpdi").
set -uf
cd "$(dirname "$0")/.." || exit 1
MPM=${MPM:-build/stage8/mpm}
SCENE=${SCENE:-tools/bench/disks_50k.cfg}
SHAPES=${SHAPES:-"linear gimp cpdi"}
export OMP_NUM_THREADS=1
[ -x "$MPM" ] || { echo "bench: $MPM not built (run make stage8)" >&2; exit 1; }
command -v valgrind >/dev/null 2>&1 || { echo "bench: shapes: valgrind not found"; exit 0; }
echo "stage 8: what the shape functions cost, $SCENE (musl, one thread)"
echo "  instructions per particle-step (callgrind, tools/task1_cost.sh)"
base=""
for s in $SHAPES; do
    read -r pts ips _ < <(bash tools/task1_cost.sh "$MPM" "$SCENE" "" "run.shape=$s run.threads=1") ||
        { echo "  $s: failed"; continue; }
    base=${base:-$ips}
    printf '  %-7s %6s points %7s  (%s x the first)\n' "$s" "$pts" "$ips" \
        "$(awk -v a="$base" -v b="$ips" 'BEGIN { printf "%.2f", b / a }')"
done
