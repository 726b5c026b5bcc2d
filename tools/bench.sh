#!/usr/bin/env bash
# make bench: speed and memory of the stage-1 solver on one thread, 2
# threads against 1 on five scenes of stages 1 to 6 (tools/bench_threads.sh), what a
# crack costs (stage 2), what the crossing step costs by search (stage 3)
# and what contact costs (stage 4: crack faces; bodies through contact groups);
# error against cost (stage 5, a subset of make fig-tradeoff) and, at the
# end, CRAMP against XEFG on the DCB (stage 6, tools/bench_xefg_dcb.sh),
# what a growing crack costs XEFG against a stationary one (stage 6,
# tools/bench_xefg_growth.sh), what the J-integral and growth cost (stage 7,
# tools/bench_growth.sh) and what the shape functions cost (stage 8,
# tools/bench_shapes.sh).
#
# Speed: particle-steps per second on the two Sulsky disks refined to about
# 50,000 and 200,000 points (tools/bench/disks_*.cfg).  Each case runs N
# steps; the program times its own time loop (its last line says "N steps
# in T s"), so reading the scene, making the points and writing the final
# output do not count.  The rate is the best of REPEAT runs: on a shared
# virtual machine the slow runs measure the neighbours, not the code.
# Set PIN="taskset -c K" to pin to a CPU.
#
# Memory per point, two ways:
#   arrays   - what the solver's arrays hold for n points: 14 doubles and
#              3 ints per point (particles.h) plus 9 doubles per grid slot
#              and a flag byte per node (grid.h), divided by n;
#   measured - peak resident set (GNU time's "Maximum resident set size")
#              of the run minus that of the small tests/1-mpm/scenes/disks.cfg
#              run (program, libraries, stack), divided by n.  This counts
#              the spare capacity of arrays grown by doubling.
#
# Environment: MPM (default build/stage1/mpm), SCHEMES (default
# "usl musl usf"), REPEAT (default 5), PIN (e.g. "taskset -c 2"), STEPS50K / STEPS200K (N),
# THREAD_REPEAT (default 3: the threads block's runs of each kind), XGROW_REPEAT
# (default 3: the pairs of tools/bench_xefg_growth.sh).
set -u
cd "$(dirname "$0")/.."
MPM=${MPM:-build/stage1/mpm}
SCHEMES=${SCHEMES:-"usl musl usf"}
REPEAT=${REPEAT:-5}
GOAL_RATE=6e6          # particle-steps per second, one thread, 200k points
GOAL_BYTES=350         # bytes per point at most
LIMIT_INSTR=657        # instructions per particle-step, uncracked DCB, stage 1 (650 on
                       # 2026-11-28 with the stencils stored at Task 0, issue 29; 934 on
                       # 2026-11-27; 1031 was counted with the final points file)
WORK=$(mktemp -d "${TMPDIR:-/tmp}/mpm-bench.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
export OMP_NUM_THREADS=1
PIN=${PIN:-}
TIMEV=""
[ -x /usr/bin/time ] && TIMEV="/usr/bin/time"

[ -x "$MPM" ] || { echo "bench: $MPM not built (run make stage1)" >&2; exit 1; }

# header SCENE -> "points dt nx ny"
header() {
    local line
    line=$($MPM "$1" -q -o "$WORK/probe" run.time=1e-9 | head -1) || return 1
    echo "$line" | sed -E 's/.*: ([0-9]+) points, grid ([0-9]+) x ([0-9]+) cells, dt = ([0-9.eE+-]+) ms.*/\1 \4 \2 \3/'
}

# peak_kb SCENE [overrides] -> peak RSS in kB
peak_kb() {
    local scene=$1
    shift
    $TIMEV -v $MPM "$scene" -q -o "$WORK/mem" "$@" 2>&1 >/dev/null |
        awk -F: '/Maximum resident set size/ { gsub(/ /, "", $2); print $2 }'
}

# steps_time SCENE SCHEME N DT -> seconds of N steps alone: the best of
# REPEAT runs of the time loop as the program itself times it (set-up and
# the final output excluded), or "fail"
steps_time() {
    local r t best="" time
    time=$(awk -v n="$3" -v dt="$4" 'BEGIN { printf "%.17g", (n - 0.5) * dt }')
    for ((r = 0; r < REPEAT; r++)); do
        if ! $PIN ${RUN:-$MPM} "$1" -q -o "$WORK/run" run.update="$2" run.time="$time" \
                >"$WORK/out" 2>"$WORK/err"; then
            echo fail
            return
        fi
        t=$(sed -nE 's/.*steps in ([0-9.]+) s.*/\1/p' "$WORK/out")
        best=$(awk -v t="$t" -v m="$best" 'BEGIN { print (m == "" || t < m) ? t : m }')
    done
    echo "$best"
}

# pair_ratios MPM SCENE_A SCENE_B N DT -> "median list": REPEAT pairs of runs
# of N steps, each pair both scenes one after the other, the ratio B / A of
# each pair (neighbours slow both alike), and the median of the ratios
pair_ratios() {
    local r a b ratios=()
    for ((r = 0; r < REPEAT; r++)); do
        a=$(REPEAT=1 RUN=$1 steps_time "$2" musl "$4" "$5")
        b=$(REPEAT=1 RUN=$1 steps_time "$3" musl "$4" "$5")
        [ "$a" = fail ] || [ "$b" = fail ] && continue
        ratios+=("$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.4f", b / a }')")
    done
    [ ${#ratios[@]} -gt 0 ] || return 1
    echo "$(printf '%s\n' "${ratios[@]}" | sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }') ${ratios[*]}"
}

printf 'mpm bench: %s, one thread%s\n' "$MPM" "${PIN:+ ($PIN)}"
printf 'CPU: %s\n' "$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null)"
printf 'timing: the time loop of N steps as the program measures it, best of %s runs\n' "$REPEAT"
printf 'load average before: %s\n\n' "$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)"
printf '%-16s %8s %7s %6s %12s %14s\n' scene points scheme N "s per step" "particle-steps/s"

declare -A RATE NPTS
for case in 50k 200k; do
    scene=tools/bench/disks_$case.cfg
    read -r npts dt nx ny < <(header "$scene") || { echo "bench: cannot read $scene" >&2; exit 1; }
    NPTS[$case]=$npts
    if [ "$case" = 50k ]; then N=${STEPS50K:-400}; else N=${STEPS200K:-200}; fi
    for scheme in $SCHEMES; do
        best=$(steps_time "$scene" "$scheme" "$N" "$dt")
        if [ "$best" = fail ]; then
            printf '%-16s %8d %7s %6d %12s %14s   (%s)\n' "disks_$case" "$npts" "$scheme" "$N" \
                - - "$(tail -1 "$WORK/err")"
            continue
        fi
        rate=$(awk -v n="$npts" -v N="$N" -v d="$best" 'BEGIN { printf "%.4g", n * N / d }')
        RATE[$case.$scheme]=$rate
        printf '%-16s %8d %7s %6d %12.4g %14.3g\n' "disks_$case" "$npts" "$scheme" "$N" \
            "$(awk -v N="$N" -v d="$best" 'BEGIN { print d / N }')" "$rate"
    done
done

echo
printf 'memory per point (200k scene)\n'
read -r npts dt nx ny < <(header tools/bench/disks_200k.cfg)
arrays=$(awk -v n="$npts" -v nx="$nx" -v ny="$ny" 'BEGIN {
    nodes = (nx + 1) * (ny + 1)
    printf "%.0f", (n * (14 * 8 + 3 * 4 + 112) + nodes * (9 * 8 + 1)) / n }')
printf '  arrays:   %s bytes/point (points 124 B each, their stencils 112 B + grid %d nodes x 73 B)\n' \
    "$arrays" "$(( (nx + 1) * (ny + 1) ))"
if [ -n "$TIMEV" ]; then
    base=$(peak_kb tests/1-mpm/scenes/disks.cfg run.time=1e-9)
    big=$(peak_kb tools/bench/disks_200k.cfg run.time=1e-9)
    if [ -n "$base" ] && [ -n "$big" ]; then
        measured=$(awk -v a="$big" -v b="$base" -v n="$npts" 'BEGIN { printf "%.0f", (a - b) * 1024 / n }')
        printf '  measured: %s bytes/point (peak RSS %s kB minus %s kB for disks.cfg)\n' \
            "$measured" "$big" "$base"
    fi
else
    echo "  measured: /usr/bin/time not found, skipped"
fi

echo
# the share of a run that is not its time loop (set-up, and the final
# points written), by output format: 200 steps of the 200k disks (musl)
printf 'set-up and output, 200 steps of the 200k disks (musl), by run.output:\n'
read -r npts dt nx ny < <(header tools/bench/disks_200k.cfg)
time200=$(awk -v dt="$dt" 'BEGIN { printf "%.17g", 199.5 * dt }')
for fmt in ascii binary; do
    t0=$(date +%s.%N)
    if ! $PIN $MPM tools/bench/disks_200k.cfg -q -o "$WORK/fmt" run.update=musl \
            run.time="$time200" run.output="\"$fmt\"" >"$WORK/out" 2>"$WORK/err"; then
        printf '  %-6s failed: %s\n' "$fmt" "$(tail -1 "$WORK/err")"
        continue
    fi
    t1=$(date +%s.%N)
    loop=$(sed -nE 's/.*steps in ([0-9.]+) s.*/\1/p' "$WORK/out")
    awk -v a="$t0" -v b="$t1" -v l="$loop" -v f="$fmt" 'BEGIN {
        w = b - a; printf "  %-6s run %.2f s, time loop %.2f s: %.1f %% outside the loop\n",
        f, w, l, 100 * (w - l) / w }'
done

echo
# threads: 2 against 1 on the issue's scenes (stages 1 and 5: the 200k
# disks; 3: the cracked DCB, indexed; 4: bodies in contact; 6: an XEFG
# plate), tools/bench_threads.sh (it runs alone too)
WORK="$WORK" REPEAT="${THREAD_REPEAT:-3}" PIN="$PIN" bash tools/bench_threads.sh
echo
r=${RATE[200k.musl]:-}
printf 'goal: >= %g particle-steps/s on one thread at 200k points; <= %d bytes/point\n' \
    "$GOAL_RATE" "$GOAL_BYTES"
if [ -n "$r" ]; then
    printf 'stage 1 (musl, 200k): %s particle-steps/s = %.2f x the goal; ' "$r" \
        "$(awk -v r="$r" -v g="$GOAL_RATE" 'BEGIN { print r / g }')"
else
    printf 'stage 1 (musl, 200k): no rate; '
fi
printf '%s bytes/point (arrays) = %s the limit\n' "$arrays" \
    "$(awk -v a="$arrays" -v g="$GOAL_BYTES" 'BEGIN { print (a <= g ? "within" : "over") }')"

# ---- stage 2: what a crack costs ---------------------------------------------
S2=build/stage2/mpm
if [ -x "$S2" ]; then
    echo
    echo "stage 2: the refined DCB with and without its crack (same points), musl"
    N=${STEPSDCB:-300}
    read -r npts dt nx ny < <(MPM=$S2 header tools/bench/dcb_crack.cfg)
    printf '%-26s %8s %6s %12s %14s\n' run points N "s per step" "particle-steps/s"
    declare -A T
    for run in "stage1 dcb_nocrack" "stage2 dcb_nocrack" "stage2 dcb_crack"; do
        read -r st scene <<<"$run"
        T[$run]=$(RUN=build/$st/mpm steps_time "tools/bench/$scene.cfg" musl "$N" "$dt")
        if [ "${T[$run]}" = fail ]; then
            printf '%-26s failed: %s\n' "$run" "$(tail -1 "$WORK/err")"
            continue
        fi
        printf '%-26s %8d %6d %12.4g %14.3g\n' "$run" "$npts" "$N" \
            "$(awk -v N="$N" -v d="${T[$run]}" 'BEGIN { print d / N }')" \
            "$(awk -v n="$npts" -v N="$N" -v d="${T[$run]}" 'BEGIN { print n * N / d }')"
    done
    a=${T[stage2 dcb_nocrack]} b=${T[stage2 dcb_crack]} c=${T[stage1 dcb_nocrack]}
    if [ "$a" != fail ] && [ "$b" != fail ] && [ "$c" != fail ]; then
        printf 'crack overhead: time with crack / without = %.2f (the paper: about 1.1 with extent screening)\n' \
            "$(awk -v a="$a" -v b="$b" 'BEGIN { print b / a }')"
    fi

    # instructions do not depend on the neighbours: count them (callgrind,
    # tools/task1_cost.sh: 30 minus 10 steps of the time loop, per particle-step)
    if command -v valgrind >/dev/null 2>&1; then
        echo "instructions per particle-step (valgrind callgrind, 30 minus 10 steps; deterministic):"
        declare -A I
        for run in "stage1 dcb_nocrack" "stage2 dcb_nocrack" "stage2 dcb_crack"; do
            read -r st scene <<<"$run"
            read -r _ whole _ < <(bash tools/task1_cost.sh "build/$st/mpm" "tools/bench/$scene.cfg")
            I[$run]=${whole:-failed}
            printf '  %-24s %6s instructions\n' "$run" "${I[$run]}"
        done
        printf '  crack overhead in instructions: %.2f\n' \
            "$(awk -v a="${I[stage2 dcb_nocrack]}" -v b="${I[stage2 dcb_crack]}" 'BEGIN { print b / a }')"
        printf '  no crack, stage 2 / stage 1: %.3f (a scene without cracks costs what stage 1 costs)\n' \
            "$(awk -v a="${I[stage1 dcb_nocrack]}" -v b="${I[stage2 dcb_nocrack]}" 'BEGIN { print b / a }')"
        # the seams (hook lists, field table, stencil, law table) may not
        # cost an instruction
        printf '  no crack, stage 1: %s instructions per particle-step, limit %s: %s\n' \
            "${I[stage1 dcb_nocrack]}" "$LIMIT_INSTR" \
            "$(awk -v a="${I[stage1 dcb_nocrack]}" -v l="$LIMIT_INSTR" 'BEGIN { print (a <= l ? "within" : "OVER") }')"
    fi
fi

# ---- stage 3: what the crossing step costs, by search -------------------------
S3=build/stage3/mpm
if [ -x "$S3" ] && command -v valgrind >/dev/null 2>&1; then
    echo
    echo "stage 3: the crossing step (Task 1 with cracks) by search, instructions per"
    echo "particle-step (callgrind, deterministic; musl)"
    task1() { bash tools/task1_cost.sh "$S3" "$@"; }
    printf '%-34s %8s %9s %12s %12s\n' scene points search "whole step" "Task 1"
    declare -A W1 T1
    for scene in figures/fig1/dcb_full.cfg tools/bench/dcb_crack_2x.cfg tools/bench/dcb_crack.cfg; do
        for search in plain screened indexed; do
            read -r pts whole t1 < <(task1 "$scene" "$search")
            W1[$scene.$search]=$whole
            T1[$scene.$search]=$t1
            printf '%-34s %8d %9s %12s %12s\n' "$scene" "$pts" "$search" "$whole" "$t1"
        done
    done
    big=tools/bench/dcb_crack.cfg
    read -r pts nocrack t1 < <(task1 tools/bench/dcb_nocrack.cfg "")
    printf 'crossing step, refined DCB: plain / screened = %.1f, plain / indexed = %.1f (the paper: about 10 from screening)\n' \
        "$(awk -v a="${T1[$big.plain]}" -v b="${T1[$big.screened]}" 'BEGIN { print a / b }')" \
        "$(awk -v a="${T1[$big.plain]}" -v b="${T1[$big.indexed]}" 'BEGIN { print a / b }')"
    printf 'crack overhead in instructions, refined DCB, indexed: %s / %s = %.3f (goal 1.05; the paper 1.10)\n' \
        "${W1[$big.indexed]}" "$nocrack" \
        "$(awk -v a="${W1[$big.indexed]}" -v b="$nocrack" 'BEGIN { print a / b }')"

    # the same as time, pair by pair: each repeat runs both, the ratio of
    # the two; the median of the ratios (neighbours slow both alike)
    N=${STEPSDCB:-300}
    read -r npts dt nx ny < <(MPM=$S3 header "$big")
    if read -r med all < <(pair_ratios "$S3" tools/bench/dcb_nocrack.cfg "$big" "$N" "$dt"); then
        printf 'crack overhead in time, refined DCB, indexed, %d steps, pair by pair: median %s of %s\n' \
            "$N" "$med" "$all"
    fi
fi

# ---- a long crack: set-up must not be quadratic in its segments -------------
# (two steps of 0.015 ms: the program refuses a run shorter than one step)
if [ -x "$S3" ]; then
    echo
    awk 'BEGIN {
        n = 100001; pi = 3.14159265358979
        print "grid = { origin = [0.0, 0.0]; cells = [100, 100]; cell_size = [1.0, 1.0]; };"
        print "run = { time = 1.0; snapshots = 0; };"
        print "materials = ( { name = \"m\"; E = 1.0; nu = 0.3; rho = 1.0e-3; } );"
        print "bodies = ( { material = \"m\"; rectangle = { min = [0.5, 30.0]; max = [99.5, 70.0]; }; } );"
        printf "cracks = ( { points = ( "
        for (k = 0; k < n; k++)
            printf "%s[%.9f, %.9f]", (k ? ", " : ""), 1 + 98 * k / (n - 1),
                   50 + 10 * sin(2 * pi * 20 * k / (n - 1))
        print " ); } );"
    }' >"$WORK/long_crack.cfg"
    best=""
    for ((r = 0; r < REPEAT; r++)); do
        t0=$(date +%s.%N)
        $S3 "$WORK/long_crack.cfg" -q -o "$WORK/long" run.time=0.02 >/dev/null || { best=fail; break; }
        t1=$(date +%s.%N)
        best=$(awk -v a="$t0" -v b="$t1" -v m="$best" 'BEGIN { t = b - a; print (m == "" || t < m) ? t : m }')
    done
    printf 'a crack of 100,000 segments (a sine wave): read, checked and indexed in %s s (best of %s; goal about 1 s)\n' \
        "$best" "$REPEAT"
fi

# ---- stage 4: what crack contact costs ----------------------------------------
S4=build/stage4/mpm
if [ -x "$S4" ] && command -v valgrind >/dev/null 2>&1; then
    echo
    echo "stage 4: the refined DCB, instructions per particle-step (callgrind, musl,"
    echo "indexed search): uncracked, cracked, cracked with frictionless contact"
    read -r pts w1 t < <(bash tools/task1_cost.sh build/stage1/mpm tools/bench/dcb_nocrack.cfg "")
    read -r pts w4n t < <(bash tools/task1_cost.sh "$S4" tools/bench/dcb_nocrack.cfg "")
    read -r pts w3 t < <(bash tools/task1_cost.sh build/stage3/mpm tools/bench/dcb_crack.cfg indexed)
    read -r pts w4 t < <(bash tools/task1_cost.sh "$S4" tools/bench/dcb_crack.cfg indexed)
    read -r pts w4c t < <(bash tools/task1_cost.sh "$S4" tools/bench/dcb_crack_contact.cfg indexed)
    printf '  %-40s %6s\n' "stage 1, no crack" "$w1" "stage 4, no crack" "$w4n" \
        "stage 3, crack" "$w3" "stage 4, crack without contact" "$w4" \
        "stage 4, crack with contact" "$w4c"
    printf 'no crack, stage 4 / stage 1: %.3f; crack without contact, stage 4 / stage 3: %.3f\n' \
        "$(awk -v a="$w1" -v b="$w4n" 'BEGIN { print b / a }')" \
        "$(awk -v a="$w3" -v b="$w4" 'BEGIN { print b / a }')"
    printf 'contact overhead: with / without contact %.3f; with contact / no crack %.3f\n' \
        "$(awk -v a="$w4" -v b="$w4c" 'BEGIN { print b / a }')" \
        "$(awk -v a="$w1" -v b="$w4c" 'BEGIN { print b / a }')"
    N=${STEPSDCB:-300}
    read -r npts dt nx ny < <(MPM=$S4 header tools/bench/dcb_crack.cfg)
    if read -r med all < <(pair_ratios "$S4" tools/bench/dcb_crack.cfg tools/bench/dcb_crack_contact.cfg "$N" "$dt"); then
        printf 'contact overhead in time, refined DCB, %d steps, pair by pair: median %s of %s\n' \
            "$N" "$med" "$all"
    fi
    echo
    echo "stage 4: contact between bodies, the 50k disks, instructions per particle-step"
    echo "(callgrind, musl): one field; each disk its own group, apart; touching"
    read -r pts d1 t < <(bash tools/task1_cost.sh build/stage1/mpm tools/bench/disks_50k.cfg "")
    read -r pts d4 t < <(bash tools/task1_cost.sh "$S4" tools/bench/disks_50k_contact.cfg "")
    read -r pts d4t t < <(bash tools/task1_cost.sh "$S4" tools/bench/disks_50k_touching.cfg "")
    printf '  %-40s %6s\n' "stage 1, one field" "$d1" "stage 4, two groups, apart" "$d4" \
        "stage 4, two groups, touching" "$d4t"
    printf 'contact groups over one field: apart %.3f, touching %.3f\n' \
        "$(awk -v a="$d1" -v b="$d4" 'BEGIN { print b / a }')" \
        "$(awk -v a="$d1" -v b="$d4t" 'BEGIN { print b / a }')"
fi

# ---- stages 5-8: a scene without cracks or contact costs what stage 1 costs ----
S5=build/stage5/mpm
if [ -x "$S5" ] && command -v valgrind >/dev/null 2>&1; then
    echo
    echo "stages 5 to 8: the 50k disks (no cracks, no contact), each against stage 1"
    read -r pts i1 t < <(bash tools/task1_cost.sh build/stage1/mpm tools/bench/disks_50k.cfg "")
    for st in 5 6 7 8; do
        [ -x "build/stage$st/mpm" ] || continue
        read -r pts i5 t < <(bash tools/task1_cost.sh "build/stage$st/mpm" tools/bench/disks_50k.cfg "")
        printf '  instructions per particle-step (callgrind, musl): stage 1 %s, stage %s %s: %s\n' \
            "$i1" "$st" "$i5" "$(awk -v a="$i1" -v b="$i5" 'BEGIN { d = (b - a) / a
                print (d <= 0.001 && d >= -0.001) ? "same within 0.1 %" : "DIFFERENT" }')"
    done
    N=${STEPS50K:-200}
    read -r npts dt nx ny < <(MPM=$S5 header tools/bench/disks_50k.cfg)
    ratios=()
    for ((r = 0; r < REPEAT; r++)); do          # pairs: neighbours slow both
        a=$(REPEAT=1 RUN=build/stage1/mpm steps_time tools/bench/disks_50k.cfg musl "$N" "$dt")
        b=$(REPEAT=1 RUN=$S5 steps_time tools/bench/disks_50k.cfg musl "$N" "$dt")
        ratios+=("$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.3f", b / a }')")
    done
    med=$(printf '%s\n' "${ratios[@]}" | sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }')
    printf '  time of %d steps, stage 5 / stage 1, pair by pair: median %s of %s (goal within 2 %%)\n' \
        "$N" "$med" "${ratios[*]}"
    echo
    echo "stage 5: what contact between bodies costs USAVG (its Task 2 adds the held-contact"
    echo "pass before the first stress update), the 50k disks, one field against touching"
    for sch in musl usavg; do
        read -r pts c1 t < <(bash tools/task1_cost.sh "$S5" tools/bench/disks_50k.cfg "" "run.update=$sch")
        read -r pts c2 t < <(bash tools/task1_cost.sh "$S5" tools/bench/disks_50k_touching.cfg "" "run.update=$sch")
        printf '  %-6s one field %5s, two groups touching %5s: contact adds %s per particle-step\n' \
            "$sch" "$c1" "$c2" "$((c2 - c1))"
    done
fi

# ---- error against cost ------------------------------------------------------
# A subset of make fig-tradeoff (figures/fig-tradeoff/make.sh, whose runs
# these are): the beam impact to 2 ms, musl and usavg at cfl 0.1 and 0.5,
# error max |E/E0 - 1|; the DCB at about 2 and 1.5 mm with 2 x 2 points per
# cell, error of the crack opening against a converged Q4 of the same loads.
# One run each (about 40 s): the loop times move with the neighbours.
S5=build/stage5/mpm
if [ -x "$S5" ]; then
    echo
    echo "error against cost (stage 5; loop s: the time loop, one run each; error: beam"
    echo "impact to 2 ms max |E/E0 - 1|, DCB |opening / converged Q4 - 1|)"
    if MPM=$S5 SCHEMES="musl usavg" CFLS="0.1 0.5" DCB_GRIDS="51:2:2 67:1.5:2" \
            TRADEOFF_RUNS="$WORK/tradeoff" TRADEOFF_TXT="$WORK/tradeoff.txt" PLOT=0 \
            bash figures/fig-tradeoff/make.sh >"$WORK/tradeoff.log" 2>&1; then
        printf '%-22s %8s %11s\n' setting "loop s" error
        awk -F, '{ printf "%-22s %8s %11s\n", "beam " $1, $3, $4 }' "$WORK/tradeoff/beam.csv"
        awk -F, '{ printf "%-22s %8s %11s\n", "dcb " $1, $3, $4 }' "$WORK/tradeoff/dcb.csv"
        grep 'unstable' "$WORK/tradeoff.txt" | sed 's/^/  /'
    else
        echo "  failed:"; tail -5 "$WORK/tradeoff.log" | sed 's/^/  /'
    fi
fi

# ---- stage 6: CRAMP against XEFG on the DCB ------------------------------------
# A subset of make fig-xefg-dcb: tools/bench_xefg_dcb.sh (it runs alone too).
S6=build/stage6/mpm
if [ -x "$S6" ]; then
    echo
    MPM=$S6 WORK="$WORK" bash tools/bench_xefg_dcb.sh
    # a growing crack against the stationary one: tools/bench_xefg_growth.sh
    # (it runs alone too; about 40 s a pair)
    echo
    MPM=$S6 WORK="$WORK" REPEAT="${XGROW_REPEAT:-3}" bash tools/bench_xefg_growth.sh
fi

# ---- stage 7: what J and growth cost -----------------------------------------
# tools/bench_growth.sh (it runs alone too).
S7=build/stage7/mpm
if [ -x "$S7" ]; then
    echo
    MPM=$S7 WORK="$WORK" REPEAT="$REPEAT" bash tools/bench_growth.sh
fi

# ---- stage 8: what the shape functions cost ----------------------------------
# tools/bench_shapes.sh (it runs alone too).
S8=build/stage8/mpm
if [ -x "$S8" ]; then
    echo
    MPM=$S8 bash tools/bench_shapes.sh
fi
