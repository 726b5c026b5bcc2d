#!/usr/bin/env bash
# make bench: CRAMP against XEFG on the DCB, a subset of make fig-xefg-dcb
# (figures/fig-xefg-dcb/make.sh, whose runs these are): both methods at the
# coarsest grids, h = 3 and 2 mm, the scene's load.  For each, three runs
# (the tip at a0 and one cell either side): the crack-mouth opening against
# the converged Q4 FEA and the energy release rate G from the compliance
# against the FEA's, the time loop of the run at a0 and its particle-steps
# per second.  One run each (about two minutes on a loaded machine, nine
# tenths of it XEFG): the loop times move with the neighbours.
#
# tools/bench.sh calls it; `bash tools/bench_xefg_dcb.sh` runs it alone.
# Environment: MPM (default build/stage6/mpm), XDCB_GRIDS ("N:h ...",
# default "35:3 51:2"; "35:3" halves the time), WORK (a folder for the
# runs; default a new one, removed at the end).
set -u
cd "$(dirname "$0")/.."
MPM=${MPM:-build/stage6/mpm}
GRIDS=${XDCB_GRIDS:-"35:3 51:2"}
if [ -z "${WORK:-}" ]; then
    WORK=$(mktemp -d "${TMPDIR:-/tmp}/mpm-bench-xdcb.XXXXXX")
    trap 'rm -rf "$WORK"' EXIT
fi
[ -x "$MPM" ] || { echo "bench: $MPM not built (run make stage6)" >&2; exit 1; }

echo "CRAMP against XEFG on the DCB (stage 6, figures/fig1/dcb_full.cfg on grids"
echo "of h mm, 2 x 2 points per cell; errors against the converged Q4 FEA: the"
echo "crack-mouth opening, G from the compliance over a0 -/+ dx; loop s: the time"
echo "loop of the run at a0, one run each; make fig-xefg-dcb has the finer grids)"
if MPM=$MPM SERIES="mpm xefg" GRIDS="$GRIDS" XDCB_RUNS="$WORK/xdcb" \
        XDCB_TXT="$WORK/xdcb.txt" PLOT=0 \
        bash figures/fig-xefg-dcb/make.sh >"$WORK/xdcb.log" 2>&1; then
    # results.csv: series,method,load,h,N,points,steps,loop,loop3,open,
    # open_fea,open_err,G,G_fea,G_err
    printf '%-6s %4s %7s %10s %8s %8s %16s\n' method h points "opening %" "G %" \
        "loop s" "particle-steps/s"
    awk -F, 'NR > 1 { printf "%-6s %4s %7s %+10.3f %+8.3f %8.3f %16.3g\n",
        $2, $4, $6, 100 * $12, 100 * $15, $8, $6 * $7 / $8 }' "$WORK/xdcb/results.csv"
else
    echo "  failed:"
    tail -5 "$WORK/xdcb.log" | sed 's/^/  /'
    exit 1
fi
