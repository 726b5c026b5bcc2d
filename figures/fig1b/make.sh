#!/usr/bin/env bash
# make fig1b: the half double cantilever beam of the paper's Fig. 1 (bottom),
# damped to the static state, its points coloured by sigma_xx (blue
# compression, red tension) at their final positions with the displacements
# magnified (MAG, default 20) so that the opening shows.
#
# Writes build/figures/fig1b.png, build/figures/fig1b_summary.txt and the
# run under build/figures/fig1b/ (history.csv, particles_*.vtu with
# particles.pvd for ParaView, grid_*.csv, particles_final.csv).
#
# Environment: MPM (default build/stage1/mpm), MAG (default 20).
. "$(dirname "$0")/../lib.sh"
MAG=${MAG:-20}
SCENE=figures/fig1b/half_dcb.cfg
RUN=$OUT/fig1b
fig_mpm 1
rm -rf "$RUN" "$RUN.layout"

# the points at t = 0 (one tiny step), to measure displacements
"$MPM" "$SCENE" -q -o "$RUN.layout" run.time=1e-9 run.snapshots=0 >/dev/null || exit 1
echo "fig1b: running $SCENE ..."
fig_try "$RUN" "$SCENE"
[ "$rc" = 0 ] || fig_failed "$RUN"

# one table: x0, y0, x, y, sigma_xx (same point order in both files)
paste -d, "$RUN.layout/particles_final.csv" "$RUN/particles_final.csv" |
    awk -F, 'NR > 2 { print $1 "," $2 "," $14 "," $15 "," $18 }' >"$RUN/points.csv"

# the opening at the load line (mean y displacement of the loaded strip
# 0 <= x <= 2) and the static state, as the test measures them
summary=$OUT/fig1b_summary.txt
awk -F, -v secs="$secs" '
    FNR == 1 { file++ }
    file == 1 && $1 <= 2 { d += $4 - $2; n++ }
    file == 1 { if ($5 > smax) smax = $5; if ($5 < smin) smin = $5 }
    file == 2 && FNR > 1 { ke = $3; u = $4; t = $2 }
    END {
        P = 1e-4; h = 18; E = 0.1; I = h^3 / 12; a = 49
        eg = 2 * (1 + 0.33); g = 1.18 * eg; q = g / (1 + g)
        chi = sqrt(eg / 11 * (3 - 2 * q * q))
        ref = P * (a + chi * h)^3 / (3 * E * I)
        printf "Fig. 1 bottom, half DCB, P = 0.1 mN at a = 49 mm, cell 0.5 mm, %.0f s\n", secs
        printf "load-line opening (half specimen) %.5f mm; beam theory P (a + chi h)^3 / (3 E I), chi = %.4f: %.5f mm (%+.2f %%)\n", d / n, chi, ref, 100 * (d / n - ref) / ref
        printf "at t = %g ms: kinetic / strain energy = %.2g; 2U / (P delta) = %.5f\n", t, ke / u, 2 * u / (P * d / n)
        printf "sigma_xx range of the points: %.4g to %.4g MPa\n", smin, smax
    }' "$RUN/points.csv" "$RUN/history.csv" >"$summary"
cat "$summary"

fig_need_gnuplot "run and $summary written, no plot"
gnuplot -e "pts='$RUN/points.csv'; out='$OUT/fig1b.png'; mag=$MAG" figures/fig1b/plot.gp || exit 1
echo "fig1b: wrote $OUT/fig1b.png and $summary"
