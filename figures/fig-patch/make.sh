#!/usr/bin/env bash
# make fig-patch: the crack patch test (the paper's section 3.1 and Fig. 1,
# chapter 2): the full double cantilever beam with an explicit crack
# (figures/fig1/dcb_full.cfg, stage 2) and the half beam with the ligament
# held by symmetry (dcb_half.cfg, no crack), the same load, grid and
# damping, run to the static state (400 ms, about two seconds each).
# Matches the upper half of the full run's points to the half run's by
# position, prints the largest difference of sigma_xx and of the positions
# (also into build/figures/fig-patch.txt), and draws both side by side on
# one colour scale: build/figures/fig-patch.png.
#
# Both runs write 17 digits (run.precision = "full"), so that the
# difference measured is the runs' own, not that of rounding the output.
# Extra arguments are overrides for both runs (run.time=50 for a short one).
set -euo pipefail
cd "$(dirname "$0")/../.."
MPM=${MPM:-build/stage2/mpm}
OUT=build/figures
RUNS=build/fig-patch
make --no-print-directory "$MPM"
mkdir -p "$OUT" "$RUNS"
for half in full half; do
    "$MPM" "figures/fig1/dcb_$half.cfg" -q -o "$RUNS/$half" run.precision=full \
        run.snapshots=0 "$@" >/dev/null
done
# columns of particles_final.csv: x, y, vx, vy, sigma_xx, ...; the first
# two lines are the time and the column names
awk -F, -v full="$RUNS/full/particles_final.csv" '
    function abs(v) { return v < 0 ? -v : v }
    FNR <= 2 { next }
    FILENAME == full { if ($2 > 0) { key = sprintf("%.4f %.4f", $1, $2)
                                     n_top++; sxx[key] = $5; x[key] = $1; y[key] = $2 }
                       next }
    { key = sprintf("%.4f %.4f", $1, $2); n_half++
      if (!(key in sxx)) { missing++; next }
      matched++
      d = abs(sxx[key] - $5); if (d > dmax) dmax = d
      if (abs($5) > smax) smax = abs($5)
      d = abs(x[key] - $1); if (d > pmax) pmax = d
      d = abs(y[key] - $2); if (d > pmax) pmax = d }
    END {
      if (missing || matched != n_top) {
          printf "fig-patch: %d of %d half-run points found no point of the full run'"'"'s upper half (%d points)\n", \
                 missing, n_half, n_top > "/dev/stderr"
          exit 1
      }
      printf "points matched by position: %d (the full run'"'"'s upper half and the half run)\n", matched
      printf "max |sigma_xx full - half| = %.2g MPa, largest |sigma_xx| = %.4g MPa, ratio %.2g\n", \
             dmax, smax, dmax / smax
      printf "max |position full - half| = %.2g mm\n", pmax
      printf "label=max |sigma_xx(full) - sigma_xx(half)| = %.2g MPa (%.2g of the largest |sigma_xx|, %.4g MPa) over %d points\n", \
             dmax, dmax / smax, smax, matched
    }' "$RUNS/full/particles_final.csv" "$RUNS/half/particles_final.csv" > "$RUNS/difference.txt"
grep -v '^label=' "$RUNS/difference.txt" | tee "$OUT/fig-patch.txt"
label=$(sed -n 's/^label=//p' "$RUNS/difference.txt")
gnuplot -e "full='$RUNS/full/particles_final.csv'; half='$RUNS/half/particles_final.csv'; \
            label='$label'; out='$OUT/fig-patch.png'" figures/fig-patch/plot.gp
echo "fig-patch: $OUT/fig-patch.png, the difference in $OUT/fig-patch.txt"
