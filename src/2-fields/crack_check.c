/**
 * @file crack_check.c
 * @brief A crack may not cross itself: the check, binned so that a crack
 *        of many segments is checked in time about proportional to them.
 *
 * The bins are about square, about as many as segments: a crack whose
 * segments are short beside its extent (a line, an arc, a zigzag) puts a
 * few in each.  Long segments packed close together (an accordion of
 * strokes across the whole crack) still share bins, and cost about the
 * square of those that do.
 */
#include <math.h>
#include <stdlib.h>

#include "cracks.h"

int crack_segments_meet(const double *a, const double *b, const double *c,
                        const double *d)
{
    double d1 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    double d2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    double d3 = (d[0] - c[0]) * (a[1] - c[1]) - (d[1] - c[1]) * (a[0] - c[0]);
    double d4 = (d[0] - c[0]) * (b[1] - c[1]) - (d[1] - c[1]) * (b[0] - c[0]);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
        ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return 1;
    /* collinear touching */
    const double *p[4][3] = {{a, b, c}, {a, b, d}, {c, d, a}, {c, d, b}};
    double dd[4] = {d1, d2, d3, d4};
    for (int k = 0; k < 4; k++)
        if (dd[k] == 0 &&
            fmin(p[k][0][0], p[k][1][0]) <= p[k][2][0] &&
            p[k][2][0] <= fmax(p[k][0][0], p[k][1][0]) &&
            fmin(p[k][0][1], p[k][1][1]) <= p[k][2][1] &&
            p[k][2][1] <= fmax(p[k][0][1], p[k][1][1]))
            return 1;
    return 0;
}

/** Bin index of coordinate @p v on [lo, lo + nb * w), clamped. */
static int bin_of(double v, double lo, double w, int nb)
{
    int b = (int)floor((v - lo) / w);
    return b < 0 ? 0 : b > nb - 1 ? nb - 1 : b;
}

/// [crack_self_crossing]
int crack_self_crossing(const Crack *c, int *i, int *j)
{
    int ns = c->n - 1;
    double x0 = c->x[0], x1 = c->x[0], y0 = c->y[0], y1 = c->y[0];
    for (int k = 1; k < c->n; k++) {
        x0 = fmin(x0, c->x[k]);
        x1 = fmax(x1, c->x[k]);
        y0 = fmin(y0, c->y[k]);
        y1 = fmax(y1, c->y[k]);
    }
    /* about ns square bins over the box (a thin crack gets a row of them:
       bins as many along each side would hold a whole column of segments
       each), at least one and at most ns along a side */
    double side = sqrt((x1 - x0) * (y1 - y0) / ns);
    if (!(side > 0))                        /* a straight crack */
        side = fmax(x1 - x0, y1 - y0) / ns;
    int nbx = 1, nby = 1;
    if (side > 0) {
        nbx = (int)fmin(fmax(ceil((x1 - x0) / side), 1), ns);
        nby = (int)fmin(fmax(ceil((y1 - y0) / side), 1), ns);
    }
    /* bins a little larger than the box, so that every end point is in */
    double wx = (x1 - x0) / nbx * (1 + 1e-9) + 1e-300;
    double wy = (y1 - y0) / nby * (1 + 1e-9) + 1e-300;
    size_t nbins = (size_t)nbx * (size_t)nby;
    int *count = calloc(nbins + 1, sizeof(int)), *list = NULL;
    int total = 0, found = 0;
    if (!count)
        return -1;
    for (int pass = 0; pass < 2; pass++) {   /* count, then fill (CSR) */
        for (int s = 0; s < ns; s++) {
            int bx0 = bin_of(fmin(c->x[s], c->x[s + 1]), x0, wx, nbx);
            int bx1 = bin_of(fmax(c->x[s], c->x[s + 1]), x0, wx, nbx);
            int by0 = bin_of(fmin(c->y[s], c->y[s + 1]), y0, wy, nby);
            int by1 = bin_of(fmax(c->y[s], c->y[s + 1]), y0, wy, nby);
            for (int by = by0; by <= by1; by++)
                for (int bx = bx0; bx <= bx1; bx++) {
                    size_t b = (size_t)by * (size_t)nbx + (size_t)bx;
                    if (pass == 0)
                        count[b + 1]++;
                    else
                        list[count[b]++] = s;
                }
        }
        if (pass == 0) {                     /* count[b]: start of bin b */
            for (size_t b = 0; b < nbins; b++)
                count[b + 1] += count[b];
            total = count[nbins];
            list = malloc(sizeof(int) * ((size_t)total + 1));
            if (!list) {
                free(count);
                return -1;
            }
        }
    }
    /* after the fill, bin b holds list[count[b - 1] .. count[b]) (b > 0),
       its segments in increasing order: the pairs (s, t), s < t */
    for (size_t b = 0; b < nbins; b++) {
        int from = b ? count[b - 1] : 0, to = count[b];
        for (int u = from; u < to; u++) {
            int s = list[u];
            if (found && s > *i)
                break;
            for (int v = u + 1; v < to; v++) {
                int t = list[v];
                if (t < s + 2 || (found && s == *i && t >= *j))
                    continue;
                double a[2] = {c->x[s], c->y[s]}, e[2] = {c->x[s + 1], c->y[s + 1]};
                double f[2] = {c->x[t], c->y[t]}, g[2] = {c->x[t + 1], c->y[t + 1]};
                if (crack_segments_meet(a, e, f, g)) {
                    *i = s;
                    *j = t;
                    found = 1;
                }
            }
        }
    }
    free(count);
    free(list);
    return found;
}
/// [crack_self_crossing]
