/**
 * @file branch.c
 * @brief The branch functions of a crack tip, eq. 5 (LEFM) and eq. 6
 *        (cohesive), and their gradients (xefg.md 2.1) (chapter 6,
 *        exercise "branch jump" replaces this file).
 */
#include <math.h>

#include "branch.h"

/// [branch_functions]
int branch_functions(BranchKind kind, double m, const double tip[2],
                     const double dir[2], int side, double x, double y,
                     double *B, double *dBx, double *dBy)
{
    /* the tip's frame: x' along dir, y' its left normal */
    double len = hypot(dir[0], dir[1]);
    double cx = dir[0] / len, cy = dir[1] / len;
    double dx = x - tip[0], dy = y - tip[1];
    double xl = cx * dx + cy * dy, yl = -cy * dx + cx * dy;
    double r = hypot(xl, yl);
    if (!(r > 0))
        return 0;
    /* theta = side acos(x'/r): +-pi on the two faces (eq. 5, xefg.md 1).
     * acos(x'/r) = atan2(|y'|, x'), which keeps its accuracy near 0 and pi,
     * on the crack's line, where acos loses half the digits. */
    double s = (side > 0) - (side < 0);
    double th = s * atan2(fabs(yl), xl);
    double s2 = sin(0.5 * th), c2 = cos(0.5 * th), st = sin(th), ct = cos(th);

    /* values and the polar derivatives dB/dr, dB/dtheta */
    double dr[BRANCH_MAX], dt[BRANCH_MAX];
    int nb;
    if (kind == BRANCH_LEFM) {              /* eq. 5 */
        double sr = sqrt(r);
        B[0] = sr * s2;
        B[1] = sr * c2;
        B[2] = sr * s2 * st;
        B[3] = sr * c2 * st;
        double h = 0.5 / sr;
        dr[0] = h * s2;
        dr[1] = h * c2;
        dr[2] = h * s2 * st;
        dr[3] = h * c2 * st;
        dt[0] = sr * 0.5 * c2;
        dt[1] = -sr * 0.5 * s2;
        dt[2] = sr * (0.5 * c2 * st + s2 * ct);
        dt[3] = sr * (-0.5 * s2 * st + c2 * ct);
        nb = 4;
    } else if (kind == BRANCH_COHESIVE) {   /* eq. 6 */
        double rm = pow(r, m);
        B[0] = rm * s2;
        dr[0] = m * rm / r * s2;
        dt[0] = 0.5 * rm * c2;
        nb = 1;
    } else {
        return 0;
    }
    if (!dBx)
        return nb;

    /* grad r = (x', y')/r; grad theta = side sign(y') (-y', x')/r^2 in the
     * tip's frame (the gradient of side acos(x'/r), atan2's where side =
     * sign y'); then back to global axes */
    double sy = (yl > 0) - (yl < 0);
    double grx = xl / r, gry = yl / r;
    double gtx = -s * sy * yl / (r * r), gty = s * sy * xl / (r * r);
    for (int k = 0; k < nb; k++) {
        double gx = dr[k] * grx + dt[k] * gtx;
        double gy = dr[k] * gry + dt[k] * gty;
        dBx[k] = cx * gx - cy * gy;
        dBy[k] = cy * gx + cx * gy;
    }
    return nb;
}
/// [branch_functions]
