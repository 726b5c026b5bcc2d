/**
 * @file growth_meet.c
 * @brief Two tips meeting (issue 27): a new segment that meets another
 *        crack, or its own crack away from its tip, is not inserted. A
 *        crack that ends on another needs the junction enrichment of
 *        Rabczuk and Zi's eq. 10 (xefg.md 4.7), which we lack; without
 *        this check the two lines ran on past each other, each cohesive
 *        on the same line (chapter 6b, "Two tips meeting").
 */
#include <math.h>

#include "growth.h"

/** Twice the signed area of (a, b, p): its sign says on which side of
 *  the line a b the point p lies. */
static double orient(const double a[2], const double b[2], const double p[2])
{
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
}

/** The distance between the segments a b and p q (0 when they cross). */
static double segments_distance(const double a[2], const double b[2],
                                const double p[2], const double q[2])
{
    double o1 = orient(a, b, p), o2 = orient(a, b, q);
    double o3 = orient(p, q, a), o4 = orient(p, q, b);
    if (((o1 < 0.0 && o2 > 0.0) || (o1 > 0.0 && o2 < 0.0)) &&
        ((o3 < 0.0 && o4 > 0.0) || (o3 > 0.0 && o4 < 0.0)))
        return 0.0;                                     /* a proper cross */
    double d = fmin(growth_segment_distance(a, b, p[0], p[1]),
                    growth_segment_distance(a, b, q[0], q[1]));
    return fmin(d, fmin(growth_segment_distance(p, q, a[0], a[1]),
                        growth_segment_distance(p, q, b[0], b[1])));
}

/// [growth_meets]
int growth_meets(const Xefg *x, double h, int c, int end, const double a[2],
                 const double b[2], int *seg)
{
    for (int k = 0; k < x->ncrack; k++) {
        const CrackLine *l = &x->crack[k];
        for (int i = 0; i + 1 < l->n; i++) {
            if (k == c && i == (end ? l->n - 2 : 0))
                continue;           /* the segment the new one continues */
            double p[2] = {l->x[i], l->y[i]}, q[2] = {l->x[i + 1], l->y[i + 1]};
            if (segments_distance(a, b, p, q) <= 1e-9 * h) {
                *seg = i;
                return k;
            }
        }
    }
    return -1;
}
/// [growth_meets]
