# The crack patch test's difference: awk -F, -v full=FULL -f match.awk FULL HALF
# with FULL and HALF the particles_final.csv of the full and the half run
# (columns x, y, vx, vy, sigma_xx, ...; two header lines).  The points of
# the full run's upper half (y > 0) are matched to the half run's by their
# position rounded to 1e-4 mm (the runs agree to round-off, far below it).
# Prints the largest differences, and a last line "label=..." for the plot;
# fails when a point finds no partner.
function abs(v) { return v < 0 ? -v : v }
FNR <= 2 { next }
FILENAME == full {
    if ($2 > 0) {
        key = sprintf("%.4f %.4f", $1, $2)
        n_top++
        sxx[key] = $5
        x[key] = $1
        y[key] = $2
    }
    next
}
{
    key = sprintf("%.4f %.4f", $1, $2)
    n_half++
    if (!(key in sxx)) { missing++; next }
    matched++
    if (abs(sxx[key] - $5) > dmax) dmax = abs(sxx[key] - $5)
    if (abs($5) > smax) smax = abs($5)
    if (abs(x[key] - $1) > pmax) pmax = abs(x[key] - $1)
    if (abs(y[key] - $2) > pmax) pmax = abs(y[key] - $2)
}
END {
    if (missing || matched != n_top) {
        printf "fig-patch: %d of %d points of the half run found no point " \
               "of the full run's upper half (%d points)\n", missing, n_half,
               n_top > "/dev/stderr"
        exit 1
    }
    printf "points matched by position: %d (the full run's upper half and " \
           "the half run)\n", matched
    printf "max |sigma_xx full - half| = %.2g MPa, largest |sigma_xx| = " \
           "%.4g MPa, ratio %.2g\n", dmax, smax, dmax / smax
    printf "max |position full - half| = %.2g mm\n", pmax
    printf "label=max |sigma_xx(full) - sigma_xx(half)| = %.2g MPa (%.2g of " \
           "the largest |sigma_xx|, %.4g MPa) over %d points\n", dmax,
           dmax / smax, smax, matched
}
