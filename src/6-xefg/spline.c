/**
 * @file spline.c
 * @brief The cubic B-spline weight of the MLS approximation (eq. 15-16,
 *        xefg.md section 4).
 */
#include "spline.h"

double spline_weight(double q, double *dw, double *d2w)
{
    double w = 0.0, w1 = 0.0, w2 = 0.0;
    if (q <= 0.5) {
        /* 2/3 - 4q^2 + 4q^3 */
        w = 2.0 / 3.0 + q * q * (-4.0 + 4.0 * q);
        w1 = q * (-8.0 + 12.0 * q);
        w2 = -8.0 + 24.0 * q;
    } else if (q < 1.0) {
        /* 4/3 - 4q + 4q^2 - 4/3 q^3 = 4/3 (1 - q)^3, written so that it has
         * no cancellation near q = 1 */
        double t = 1.0 - q;
        w = 4.0 / 3.0 * t * t * t;
        w1 = -4.0 * t * t;
        w2 = 8.0 * t;
    } /* q >= 1 (or NaN): outside the support, w = 0 with its derivatives */
    if (dw)
        *dw = w1;
    if (d2w)
        *d2w = w2;
    return w;
}
