/*
 * Exercise "MLS shape functions" (chapter 6): your moving least-squares
 * shape functions with a linear basis (eq. 13-16).
 * Copy this file, fill in mls_shape(), and run
 *     make exercise EX=6-xefg/mls-shape-functions SOLUTION=your_copy.c
 * The contract is in src/6-xefg/mls.h; README.md says what is checked.
 */
#include <math.h>
#include <stddef.h>

#include "mls.h"
#include "spline.h"

int mls_shape(double x, double y, int n, const double *X, const double *Y,
              const double *d, double *phi, double *dphix, double *dphiy)
{
    /* TODO: the moment matrix A (eq. 15) in the shifted, scaled basis,
     * gamma = A^-1 p, Phi_k = gamma . p_k w_k (eq. 14) and the gradients.
     * This stub returns Shepard functions w_k / sum w with zero gradients:
     * a partition of unity that does not reproduce a linear field, so the
     * tests fail until you write them. */
    double sum = 0.0;
    int active = 0;
    for (int k = 0; k < n; k++) {
        double rx = x - X[k], ry = y - Y[k];
        phi[k] = spline_weight(sqrt(rx * rx + ry * ry) / d[k], NULL, NULL);
        sum += phi[k];
        active += phi[k] > 0.0;
    }
    if (active < 3)
        return -1;
    for (int k = 0; k < n; k++) {
        phi[k] /= sum;
        if (dphix) {
            dphix[k] = 0.0;
            dphiy[k] = 0.0;
        }
    }
    return 0;
}
