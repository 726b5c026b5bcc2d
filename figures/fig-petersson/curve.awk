# figures/fig-petersson/curve.awk: the load against the deflection of a run
# of Petersson's beam, from its history.csv (awk -F, -v v=V -v ramp=R):
# the deflection delta(t) of the held top nodes (velocity v ramped in
# linearly over ramp: v t^2 / (2 ramp), then v (t - ramp / 2)) and the
# load P = dW / d delta, W = xefg_held_work (the supports do no work, so
# W is the work of the load), by the difference of consecutive rows: the
# mean load over each interval, at its mid deflection.  Columns: deflection
# (mm), load (N), xefg_kinetic / xefg_strain, dissipated (N mm), time (ms).
function defl(t) { return t < ramp ? v * t * t / (2 * ramp) : v * (t - ramp / 2) }
NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
{
    t = $c["time"]; w = $c["xefg_held_work"]; d = defl(t)
    if (NR > 2 && d > d0)
        printf "%.6f %.4f %.5f %.4f %.4f\n", (d + d0) / 2, (w - w0) / (d - d0),
            ($c["xefg_strain"] > 0 ? $c["xefg_kinetic"] / $c["xefg_strain"] : 0),
            $c["cohesive_dissipated"], t
    d0 = d; w0 = w
}
