# Shell functions shared by the timing scripts (sourced, not run):
# tools/bench_threads.sh and tools/bench_scaling.sh.

# scene_steps MPM SCENE N WORK [OVERRIDES...] -> "points time": the scene's
# number of points and a run.time of N whole steps (N - 1/2 steps of the
# scene's dt, so rounding cannot add or drop one); nothing when the scene
# cannot be read.
scene_steps() {
    local mpm=$1 scene=$2 n=$3 work=$4 pts dt
    shift 4
    read -r pts dt < <("$mpm" "$scene" -q -o "$work/probe" run.time=1e-9 "$@" 2>&1 |
        sed -nE 's/.*: ([0-9]+) points.*dt = ([0-9.eE+-]+) ms.*/\1 \2/p')
    [ -n "${pts:-}" ] || return 0
    echo "$pts $(awk -v n="$n" -v dt="$dt" 'BEGIN { printf "%.17g", (n - 0.5) * dt }')"
}
