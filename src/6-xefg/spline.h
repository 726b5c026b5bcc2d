/**
 * @file spline.h
 * @brief The cubic B-spline weight of the EFG approximation (Rabczuk and
 *        Zi, eq. 13-16: "cubic B-spline"; xefg.md section 4).
 */
#ifndef MPM_SPLINE_H
#define MPM_SPLINE_H

/**
 * @brief The cubic spline w(q) of the normalised distance q = |x - X_I| / d_I:
 *        2/3 - 4q^2 + 4q^3 (q <= 1/2), 4/3 - 4q + 4q^2 - 4/3 q^3 (1/2 < q < 1),
 *        0 beyond.
 * @param q   normalised distance, q >= 0
 * @param dw  dw/dq (NULL: not wanted)
 * @param d2w d2w/dq2 (NULL: not wanted)
 * @return w(q)
 */
double spline_weight(double q, double *dw, double *d2w);

#endif
