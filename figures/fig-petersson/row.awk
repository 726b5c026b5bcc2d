# figures/fig-petersson/row.awk: a row of fig-petersson's table from a
# run's curve (curve.awk's output; awk -v name=NAME -v h=H -v steps=N
# -v loop=S -v coh=E -v v=V -v ramp=R): P at 0.365 and 0.607 mm against
# Petersson's 774 and 598 N, the peak and where it lies, the area under
# the curve, the tail P_e delta_e, the work to separation against
# G_f b (D - a0) = 685 N mm, the cohesive energy COH against the same, and
# the largest kinetic over strain energy after 2 ramps.  A run stopped
# before 2 mm: its P, peak and place hold; its area, tail and work do not.
function at(x,  i) { for (i = 2; i <= n; i++) if (d[i - 1] <= x && x <= d[i])
    return p[i - 1] + (p[i] - p[i - 1]) * (x - d[i - 1]) / (d[i] - d[i - 1]); return -1 }
{ n++; d[n] = $1; p[n] = $2; t = $5
  if ($2 > pk) { pk = $2; pd = $1 } if ($5 >= 2 * ramp && $3 > ke) ke = $3 }
END {
    # the area: each load times its interval, from half way to the
    # sample before to half way to the one after (the end: delta_e)
    de = v * (t - ramp / 2); area = 0
    for (i = 1; i <= n; i++) { lo = i > 1 ? (d[i - 1] + d[i]) / 2 : 0
        hi = i < n ? (d[i] + d[i + 1]) / 2 : de; area += p[i] * (hi - lo) }
    s = 0; m = 0; for (i = n; i >= 1 && d[i] > de - 0.05; i--) { s += p[i]; m++ }
    pe = s / m; tot = area + pe * de; ref = 0.137 * 50 * 100
    p1 = at(0.365); p2 = at(0.607)
    printf "%-10s %6.2f %7d %7.1f %8.1f %+7.2f %8.1f %+7.2f %7.1f %6.3f %7.1f %6.1f %7.1f %+7.2f %7.1f %+7.2f %7.4f\n",
        name, h, steps, loop, p1, 100 * (p1 / 774 - 1), p2, 100 * (p2 / 598 - 1), pk, pd,
        area, pe, tot, 100 * (tot / ref - 1), coh, 100 * (coh / ref - 1), ke
}
