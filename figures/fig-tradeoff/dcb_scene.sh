#!/usr/bin/env bash
# dcb_scene.sh N DY [K]: figures/fig1/dcb_full.cfg on a grid of dx = 100/N,
# dy, with 4 mm margins, written to standard output.  N odd puts the crack
# tip (x = 50) mid-cell, as tests/3-crossing/scenes/tip_mid_* do; K (default
# 0) moves the tip K whole cells (to 50 + K dx), so that it stays mid-cell:
# make fig-xefg-dcb's crack lengths a0 - da, a0 + da.  The crack starts one
# cell left of the body, on a node.  Used by figures/fig-tradeoff/make.sh
# and figures/fig-xefg-dcb/make.sh.
set -u
cd "$(dirname "$0")/../.."
awk -v N="$1" -v dy="$2" -v K="${3:-0}" '
    function f(v,  s) { s = sprintf("%.17g", v); return (s ~ /[.e]/) ? s : s ".0" }
    BEGIN { dx = 100 / N; nl = int(4 / dx); if (nl * dx < 4) nl++
            print "# written by figures/fig-tradeoff/dcb_scene.sh: figures/fig1/dcb_full.cfg,"
            printf "# dx = 100/%d, dy = %s, tip mid-cell, crack from one cell left\n", N, dy
            if (K != 0) printf "# the tip moved %d cells: x = 50 + %d dx\n", K, K }
    /^grid = / { g = 1 }
    g { if (/}; *$/) { printf "grid = { origin = [%s, -24.0]; cells = [%d, %d];\n", f(-nl * dx), N + 2 * nl, 48 / dy
                       printf "         cell_size = [%s, %s]; };\n", f(dx), f(dy); g = 0 }
        next }
    /^cracks = / { printf "cracks = ( { points = ( [%s, 0.0], [%s, 0.0] ); } );\n", f(-dx), f(50 + K * dx); next }
    { print }' figures/fig1/dcb_full.cfg
