/*
 * Exercise 6.1, "MLS shape functions" (chapter 6): the moment matrix of a
 * moving least-squares fit with a linear basis and the shape functions it
 * gives (eq. 13-16).  Copy this file, fill in mls_fit() and mls_shape(), and
 * run
 *     make exercise EX=6-xefg/mls-shape-functions SOLUTION=your_copy.c
 * The contract is in src/6-xefg/mls.h; README.md says what is checked.
 */
#include <lapacke.h>
#include <math.h>
#include <stddef.h>

#include "mls.h"
#include "spline.h"

int mls_fit(double x, double y, int n, const double *X, const double *Y,
            const double *d, double *w, MlsFit *fit)
{
    /* TODO: the moment matrix A (eq. 15) in the shifted, scaled basis, its
     * Cholesky factor (refuse A singular or nearly so) and gamma = A^-1 p.
     * This stub computes the weights and then pretends A = I. */
    int active = 0;
    fit->s = 0.0;
    for (int k = 0; k < n; k++) {
        double rx = x - X[k], ry = y - Y[k];
        w[k] = spline_weight(sqrt(rx * rx + ry * ry) / d[k], NULL, NULL);
        if (w[k] > 0.0) {
            active++;
            fit->s = fmax(fit->s, d[k]);
        }
    }
    if (active < 3)
        return -1;
    for (int i = 0; i < 9; i++)
        fit->U[i] = i % 4 == 0 ? 1.0 : 0.0;
    fit->gamma[0] = 1.0;
    fit->gamma[1] = fit->gamma[2] = 0.0;
    return 0;
}

int mls_shape(double x, double y, int n, const double *X, const double *Y,
              const double *d, double *phi, double *dphix, double *dphiy)
{
    /* TODO: Phi_k = gamma . p_k w_k (eq. 14); the gradients, when wanted,
     * from mls_gradient() (already written, src/6-xefg/mls_gradient.c).
     * This stub returns Shepard functions w_k / sum_j w_j: a partition of
     * unity that does not reproduce a linear field, so the tests fail
     * until you write them. */
    MlsFit fit;
    if (mls_fit(x, y, n, X, Y, d, phi, &fit))
        return -1;
    if (dphix && mls_gradient(x, y, n, X, Y, d, &fit, dphix, dphiy))
        return -1;
    double sum = 0.0;
    for (int k = 0; k < n; k++)
        sum += phi[k];
    for (int k = 0; k < n; k++)
        phi[k] /= sum;
    return 0;
}
