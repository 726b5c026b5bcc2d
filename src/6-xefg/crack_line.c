/**
 * @file crack_line.c
 * @brief The crack as a polyline: the side of a point from its closest
 *        segment (eq. 3-4), how a support disk meets the crack (eq. 1-2)
 *        and where the tips point.
 */
#include <math.h>

#include "crack_line.h"

/** Unit vector along segment k, in (*ux, *uy); (0, 0) for a repeated point. */
static void segment_dir(const CrackLine *c, int k, double *ux, double *uy)
{
    double dx = c->x[k + 1] - c->x[k], dy = c->y[k + 1] - c->y[k];
    double len = hypot(dx, dy);
    *ux = len > 0 ? dx / len : 0.0;
    *uy = len > 0 ? dy / len : 0.0;
}

/**
 * The point of segment k closest to (x, y): its parameter t in [0, 1] (0 and
 * 1 exactly at the ends, so that the end's own coordinates are used) and
 * the squared distance.
 */
static double segment_closest(const CrackLine *c, int k, double x, double y,
                              double *t)
{
    double ax = c->x[k], ay = c->y[k];
    double dx = c->x[k + 1] - ax, dy = c->y[k + 1] - ay;
    double len2 = dx * dx + dy * dy;
    double s = len2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / len2 : 0.0;
    double px, py;
    if (s <= 0) {
        s = 0;
        px = ax;
        py = ay;
    } else if (s >= 1) {
        s = 1;
        px = c->x[k + 1];
        py = c->y[k + 1];
    } else {
        px = ax + s * dx;
        py = ay + s * dy;
    }
    *t = s;
    return (x - px) * (x - px) + (y - py) * (y - py);
}

/// [crack_line_side]
int crack_line_side(const CrackLine *c, double x, double y, double *dist)
{
    int nseg = c->n - 1, kb = -1;
    double best = INFINITY, tb = 0;
    for (int k = 0; k < nseg; k++) {
        double t, d2;
        if (c->x[k + 1] == c->x[k] && c->y[k + 1] == c->y[k])
            continue;                   /* a repeated point: no segment */
        d2 = segment_closest(c, k, x, y, &t);
        if (d2 < best) {
            best = d2;
            kb = k;
            tb = t;
        }
    }
    if (kb < 0) {                       /* all its points are one point */
        if (dist)
            *dist = hypot(x - c->x[0], y - c->y[0]);
        return 0;
    }
    if (dist)
        *dist = sqrt(best);
    /* the segment that shares the closest point when it is a vertex */
    int other = -1;
    if (tb == 0 || tb == 1) {
        int step = tb == 0 ? -1 : 1;
        for (int k = kb + step; k >= 0 && k < nseg && other < 0; k += step)
            if (c->x[k + 1] != c->x[k] || c->y[k + 1] != c->y[k])
                other = k;
    }
    double ux, uy, side;
    int v = tb == 1 ? kb + 1 : kb;      /* a point of segment kb's line */
    double wx = x - c->x[v], wy = y - c->y[v];
    segment_dir(c, kb, &ux, &uy);
    /* the cross product of the segment's direction with (point - q), eq. 4 */
    side = ux * wy - uy * wx;
    if (other >= 0) {
        /* q is a vertex shared by two segments, both equally close. Their
         * pseudo-normal (the sum of the two unit normals) gives the right
         * side even where the crack folds back sharply, where the normal of
         * either segment alone can be wrong. */
        double vx, vy;
        segment_dir(c, other, &vx, &vy);
        side += vx * wy - vy * wx;
    }
    return (side > 0) - (side < 0);
}
/// [crack_line_side]

SupportCut crack_line_cut(const CrackLine *c, double x, double y, double r,
                          int *end)
{
    int e_best = -1;
    double d_best = r;
    for (int e = 0; e < 2; e++) {
        if (!c->tip[e])
            continue;
        int i = e == 0 ? 0 : c->n - 1;
        double d = hypot(x - c->x[i], y - c->y[i]);
        if (d < d_best) {      /* strictly inside the disk; the nearer tip */
            d_best = d;
            e_best = e;
        }
    }
    if (end)
        *end = e_best;
    if (e_best >= 0)
        return SUPPORT_TIP;
    for (int k = 0; k + 1 < c->n; k++) {
        double t;
        if (segment_closest(c, k, x, y, &t) < r * r)
            return SUPPORT_CUT;
    }
    return SUPPORT_UNCUT;
}

void crack_line_tip(const CrackLine *c, int end, double tip[2], double dir[2])
{
    /* the last segment of non-zero length at that end points ahead */
    int i = end == 0 ? 0 : c->n - 1, step = end == 0 ? 1 : -1;
    tip[0] = c->x[i];
    tip[1] = c->y[i];
    dir[0] = dir[1] = 0.0;
    for (int j = i + step; j >= 0 && j < c->n; j += step) {
        double dx = c->x[i] - c->x[j], dy = c->y[i] - c->y[j];
        double len = hypot(dx, dy);
        if (len > 0) {
            dir[0] = dx / len;
            dir[1] = dy / len;
            return;
        }
    }
}
