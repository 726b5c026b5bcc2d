# figures/lib.sh: what the figure scripts (figures/<name>/make.sh) share.
# A script sources it before anything else:
#
#     . "$(dirname "$0")/../lib.sh"
#
# and may then tighten the shell (set -eo pipefail); the functions below
# work with or without errexit.  Sourcing it
#   - sets -u (an unset variable is an error);
#   - goes to the repository root (the scripts name every path from there,
#     so that they run from anywhere, not only from make);
#   - sets FIG, the figure's name (its folder's: fig-tradeoff), with which
#     every message of the script and of these functions starts;
#   - sets OUT=build/figures, where the figures and their tables go, and
#     makes it.
#
# Building
#   fig_build TARGET...   make the targets, quietly (make's own errors
#                         still show); exits 1 when make fails.
#   fig_mpm STAGE         sets MPM to the solver the figure runs: the
#                         environment's MPM, or build/stageSTAGE/mpm, which
#                         it then builds (fig_build); exits 1 unless $MPM is
#                         an executable ("FIG: MPM not built").
#
# Running one case ($MPM on a scene; the solver's exit status 3 means the
# instability check stopped the run: a figure lists such a run as
# "unstable at t" and leaves it off its plot)
#   fig_run DIR SCENE [OVERRIDE...]
#                         removes DIR, runs
#                             "$MPM" SCENE -q -o DIR OVERRIDE... >DIR.log 2>&1
#                         and sets
#                           rc      its exit status: 0 or 3 (any other
#                                   status: fig_failed, which exits);
#                           secs    its wall time, s, one decimal (set-up
#                                   and output included);
#                           loop, steps   the time loop's wall time (s) and
#                                   its steps, as fig_loop; empty unless
#                                   rc is 0;
#                           why, unstable_t, unstable_msg   as fig_unstable
#                                   when rc is 3 (why is then never empty:
#                                   "unstable" when the solver's message is
#                                   missing); empty when rc is 0.
#   fig_try DIR SCENE [OVERRIDE...]
#                         the same run, the same variables, whatever the
#                         exit status: for a figure that makes something of
#                         another status (fig-stability: 1, the scene
#                         refused) or accepts only 0; it calls fig_failed
#                         itself for the rest.
#   fig_failed DIR        the run's log (DIR.log) to stderr, then
#                         "FIG: DIR failed (exit $rc)"; exits 1.
#
# Reading a run's log
#   fig_loop LOG          sets loop and steps from the program's last line,
#                         "mpm: done, output in DIR (N steps in T s, ...)":
#                         loop = T, the time loop's own wall time (no
#                         set-up, no final output), steps = N; both empty
#                         when the line is missing (a run that stopped).
#   fig_unstable LOG      from the solver's first "mpm: unstable at step N
#                         (t = T UNIT): ..." line (or "stopped at step",
#                         a run a rule ended: step_stop()) sets
#                         unstable_msg (the line), unstable_t (T, a number
#                         in the scene's time unit) and why ("unstable at
#                         T UNIT" or "stopped at T UNIT"); all three empty
#                         when there is no such line.
#
# Runs in the background
#   fig_job NAME SCENE [OVERRIDE...]
#                         fig_try into $RUNS/NAME in the background, at
#                         most $JOBS at a time, writing "rc secs loop
#                         steps" to $RUNS/NAME.rc; with REUSE=1 a run that
#                         has its .rc already is not made again. The
#                         caller waits for them (wait).
#
# Timing and the machine
#   fig_now               prints the clock, in ns (date +%s%N).
#   fig_since START       prints the seconds since START (a fig_now),
#                         "S.mmm".
#   fig_cpu               prints the CPU's model name (/proc/cpuinfo).
#   fig_load              prints the load averages over 1, 5 and 15 minutes
#                         (/proc/loadavg): a figure that reports times notes
#                         them before and after its runs.
#
# Tools
#   fig_need COMMAND PACKAGE [NOTE]
#                         exits 1 unless COMMAND is on the PATH, with a
#                         message naming the Debian PACKAGE that brings it
#                         and how to install it (sh tools/deps.sh figures,
#                         which make figN runs first) and NOTE (what the
#                         script has written so far).
#   fig_need_gnuplot [NOTE]   fig_need gnuplot gnuplot-nox [NOTE]: a script
#                         calls it before its first plot, after its runs
#                         and tables, so that those are kept without gnuplot.

set -u
FIG=$(basename "$(cd "$(dirname "$0")" && pwd)")
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
OUT=build/figures
mkdir -p "$OUT" || exit 1

fig_build() {
    make --no-print-directory "$@" >/dev/null ||
        { echo "$FIG: could not build $*" >&2; exit 1; }
}

fig_mpm() {
    MPM=${MPM:-build/stage$1/mpm}
    if [ "$MPM" = "build/stage$1/mpm" ]; then
        fig_build "$MPM"
    fi
    [ -x "$MPM" ] || { echo "$FIG: $MPM not built" >&2; exit 1; }
}

fig_loop() {
    local last
    last=$(grep -E ' \([0-9]+ steps in [0-9.eE+-]+ s' "$1" 2>/dev/null | tail -n 1) || true
    loop=$(sed -nE 's/.* \(([0-9]+) steps in ([0-9.eE+-]+) s.*/\2/p' <<<"$last")
    steps=$(sed -nE 's/.* \(([0-9]+) steps in ([0-9.eE+-]+) s.*/\1/p' <<<"$last")
}

fig_unstable() {
    unstable_msg=$(grep -m 1 -E '(unstable|stopped) at step [0-9]* \(t = ' "$1" 2>/dev/null) || true
    unstable_t=$(sed -nE 's/.*(unstable|stopped) at step [0-9]+ \(t = ([0-9.eE+-]+) [^)]*\).*/\2/p' <<<"$unstable_msg")
    why=$(sed -nE 's/.*(unstable|stopped) at step [0-9]+ \(t = ([0-9.eE+-]+) ([^)]*)\).*/\1 at \2 \3/p' <<<"$unstable_msg")
}

fig_job() {
    local name=$1
    shift
    [ "${REUSE:-0}" = 1 ] && [ -f "$RUNS/$name.rc" ] && return 0
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n || true; done
    ( fig_try "$RUNS/$name" "$@"
      echo "$rc $secs ${loop:-} ${steps:-}" >"$RUNS/$name.rc" ) &
}

fig_try() {
    local dir=$1 scene=$2 t0
    shift 2
    rm -rf "$dir"
    t0=$(fig_now)
    rc=0
    "$MPM" "$scene" -q -o "$dir" "$@" >"$dir.log" 2>&1 || rc=$?
    secs=$(awk -v a="$t0" -v b="$(fig_now)" 'BEGIN { printf "%.1f", (b - a) / 1e9 }')
    loop="" steps="" why="" unstable_t="" unstable_msg=""
    case $rc in
        0) fig_loop "$dir.log" ;;
        3) fig_unstable "$dir.log"; why=${why:-unstable} ;;
    esac
}

fig_run() {
    fig_try "$@"
    case $rc in
        0|3) ;;
        *) fig_failed "$1" ;;
    esac
}

fig_failed() {
    cat "$1.log" >&2
    echo "$FIG: $1 failed (exit $rc)" >&2
    exit 1
}

fig_now() { date +%s%N; }

fig_since() {
    local ms=$(( ($(fig_now) - $1) / 1000000 ))
    printf '%d.%03d' $((ms / 1000)) $((ms % 1000))
}

fig_cpu() { awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null; }

fig_load() { cut -d' ' -f1-3 /proc/loadavg 2>/dev/null; }

fig_need() {
    command -v "$1" >/dev/null 2>&1 && return 0
    echo "$FIG: $1 not found${3:+; $3}" >&2
    echo "  it is in the Debian package $2: sh tools/deps.sh figures installs it" \
         "(as root; make figN runs that first), or: sudo apt-get install $2" >&2
    exit 1
}

fig_need_gnuplot() { fig_need gnuplot gnuplot-nox "$@"; }
