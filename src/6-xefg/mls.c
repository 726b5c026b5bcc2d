/**
 * @file mls.c
 * @brief Moving least-squares shape functions with a linear basis
 *        (eq. 13-16): the weights, the moment matrix and the values, in a
 *        basis shifted to the evaluation point and scaled by the support
 *        radius (xefg.md pitfall 1). Their gradients are in mls_gradient.c.
 *
 * With the basis origin c and scale s held fixed, p(z) = (1, (z_x - c_x)/s,
 * (z_y - c_y)/s) and
 *
 *   Phi_k(x) = gamma(x) . p(X_k) w_k(x),   A(x) gamma(x) = p(x)   (eq. 14)
 *
 * MLS does not depend on where the basis has its origin, so c may be set
 * to x: then p(x) = (1, 0, 0), and the entries of A are of order one
 * wherever the cloud lies.
 */
#include <lapacke.h>
#include <math.h>
#include <stddef.h>

#include "mls.h"
#include "spline.h"

/** Reciprocal condition number below which A counts as singular. */
#define MLS_RCOND_MIN 1e-12

/* A += f p p^T for a symmetric 3x3 matrix stored in full, column major. */
static void add_outer(double *A, double f, const double p[3])
{
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++)
            A[i + 3 * j] += f * p[i] * p[j];
}

int mls_fit(double x, double y, int n, const double *X, const double *Y,
            const double *d, double *w, MlsFit *fit)
{
    /* The weights (eq. 15-16); the scale s is the largest radius of the
     * nodes that count. */
    int active = 0;
    double s = 0.0;
    for (int k = 0; k < n; k++) {
        double rx = x - X[k], ry = y - Y[k];
        w[k] = spline_weight(sqrt(rx * rx + ry * ry) / d[k], NULL, NULL);
        if (w[k] > 0.0) {
            active++;
            if (d[k] > s)
                s = d[k];
        }
    }
    if (active < 3)
        return -1;
    fit->s = s;

    /* The moment matrix A = sum_k p_k p_k^T w_k (eq. 15), with
     * p_k = (1, (X_k - x)/s, (Y_k - y)/s). */
    double *A = fit->U;
    for (int i = 0; i < 9; i++)
        A[i] = 0.0;
    for (int k = 0; k < n; k++) {
        if (!(w[k] > 0.0))
            continue;
        const double p[3] = {1.0, (X[k] - x) / s, (Y[k] - y) / s};
        add_outer(A, w[k], p);
    }

    /* Cholesky factor of A; refuse a singular or nearly singular A (fewer
     * than three nodes off one line). */
    double work[9];
    lapack_int iwork[3];
    double anorm = LAPACKE_dlansy_work(LAPACK_COL_MAJOR, '1', 'U', 3, A, 3, work);
    if (LAPACKE_dpotrf_work(LAPACK_COL_MAJOR, 'U', 3, A, 3) != 0)
        return -1;
    double rcond = 0.0;
    if (LAPACKE_dpocon_work(LAPACK_COL_MAJOR, 'U', 3, A, 3, anorm, &rcond,
                            work, iwork) != 0
        || !(rcond >= MLS_RCOND_MIN))
        return -1;

    /* gamma = A^-1 p(x), p(x) = (1, 0, 0) in the shifted basis (eq. 14) */
    fit->gamma[0] = 1.0;
    fit->gamma[1] = fit->gamma[2] = 0.0;
    if (LAPACKE_dpotrs_work(LAPACK_COL_MAJOR, 'U', 3, 1, A, 3, fit->gamma, 3) != 0)
        return -1;
    return 0;
}

int mls_shape(double x, double y, int n, const double *X, const double *Y,
              const double *d, double *phi, double *dphix, double *dphiy)
{
    /* the weights go to phi until the values replace them */
    MlsFit fit;
    if (mls_fit(x, y, n, X, Y, d, phi, &fit))
        return -1;
    if (dphix && mls_gradient(x, y, n, X, Y, d, &fit, dphix, dphiy))
        return -1;

    /* Phi_k = gamma . p_k w_k (eq. 14) */
    const double s = fit.s, *gamma = fit.gamma;
    for (int k = 0; k < n; k++) {
        double w = phi[k];
        if (!(w > 0.0)) {
            phi[k] = 0.0;
            continue;
        }
        const double p[3] = {1.0, (X[k] - x) / s, (Y[k] - y) / s};
        phi[k] = (gamma[0] * p[0] + gamma[1] * p[1] + gamma[2] * p[2]) * w;
    }
    return 0;
}
