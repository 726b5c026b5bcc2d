/**
 * @file crossing.c
 * @brief The line-crossing test by signed triangle areas (Appendix, eq. 33
 *        and subtasks 2-4): one segment, and one crack (chapter 2,
 *        exercise "line crossing" replaces this file).
 */
#include "cracks.h"

/** Sign of the signed area A(1,2,3) of eq. 33: +1, -1 or exactly 0. */
static int area_sign(double x1, double y1, double x2, double y2, double x3,
                     double y3)
{
    double a = x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2);
    return (a > 0) - (a < 0);
}

/// [segment_crossing]
/**
 * Does the line from point 1 (particle) to point 2 (node) cross segment
 * 3 -> 4?  +1 with the particle above, -1 below, 0 not crossed.
 * Segments are half open, [3, 4), so that a node or a line through a point
 * shared by two segments counts once; the crack's last segment keeps its
 * end point 4 (@p last), and a line through the crack's first point only
 * grazes the crack (@p first).
 */
static inline __attribute__((always_inline)) int
segment_crossing(double x1, double y1, double x2, double y2, double x3,
                 double y3, double x4, double y4, int first, int last)
{
    int a341 = area_sign(x3, y3, x4, y4, x1, y1);
    int a342 = area_sign(x3, y3, x4, y4, x2, y2);
    if (a341 == 0 || a341 * a342 > 0) /* particle on the crack's line, or */
        return 0;                     /* particle and node on one side */
    int a123 = area_sign(x1, y1, x2, y2, x3, y3);
    int a124 = area_sign(x1, y1, x2, y2, x4, y4);
    if (a123 * a124 > 0)          /* both ends of the crack on one side */
        return 0;
    /* subtask 3, particle above: (-,+,+,-) (-,+,+,0) (0,+,+,0) (-,0,+,0) */
    if (a341 > 0 && a342 <= 0) {
        if (a123 < 0 && a124 > 0)
            return 1;
        if (a342 == 0 && ((a123 == 0 && a124 > 0) ||
                          (a123 < 0 && a124 == 0 && last)))
            return 1;
        /* the line passes through an interior point of the polyline */
        if (a342 < 0 && a123 == 0 && a124 > 0 && !first)
            return 1;
        return 0;
    }
    /* particle below: (+,-,-,+) (+,-,-,0) (0,-,-,0) (+,0,-,0) */
    if (a341 < 0 && a342 >= 0) {
        if (a123 > 0 && a124 < 0)
            return -1;
        if (a342 == 0 && ((a123 == 0 && a124 < 0) ||
                          (a123 > 0 && a124 == 0 && last)))
            return -1;
        if (a342 > 0 && a123 == 0 && a124 < 0 && !first)
            return -1;
    }
    return 0;
}
/// [segment_crossing]

/// [crack_segment_side]
int crack_segment_side(const Crack *c, int k, double px, double py, double nx,
                       double ny)
{
    return segment_crossing(px, py, nx, ny, c->x[k], c->y[k], c->x[k + 1],
                            c->y[k + 1], k == 0, k + 2 == c->n);
}
/// [crack_segment_side]

/// [crack_crossing]
int crack_crossing(const Crack *c, double px, double py, double nx, double ny)
{
    int count = 0, sum = 0;
    for (int k = 0; k + 1 < c->n; k++) {
        int s = crack_segment_side(c, k, px, py, nx, ny);
        count += s != 0;
        sum += s;
    }
    /* subtask 4: an odd number crosses; the side from all of them */
    return (count % 2) ? (sum > 0) - (sum < 0) : 0;
}
/// [crack_crossing]
