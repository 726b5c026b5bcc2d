/**
 * @file mls.c
 * @brief Moving least-squares shape functions with a linear basis
 *        (eq. 13-16), in a basis shifted to the evaluation point and scaled
 *        by the support radius (xefg.md pitfall 1).
 *
 * With the basis origin c and scale s held fixed, p(z) = (1, (z_x - c_x)/s,
 * (z_y - c_y)/s) and
 *
 *   Phi_k(x) = gamma(x) . p(X_k) w_k(x),   A(x) gamma(x) = p(x)   (eq. 14)
 *
 * so that, differentiating A gamma = p,
 *
 *   A gamma_x = p_x - A_x gamma,   dPhi_k/dx = gamma_x . p_k w_k + gamma . p_k w_k,x.
 *
 * MLS does not depend on where the basis has its origin, so once the
 * derivatives are taken c may be set to x: then p(x) = (1, 0, 0), p_x =
 * (0, 1/s, 0), p_y = (0, 0, 1/s), and the entries of A are of order one
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

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

int mls_shape(double x, double y, int n, const double *X, const double *Y,
              const double *d, double *phi, double *dphix, double *dphiy)
{
    const int grad = dphix != NULL;

    /* The weights (eq. 15-16) and their gradients, kept in the output
     * arrays until the second pass; the scale s is the largest radius of
     * the nodes that count. */
    int active = 0;
    double s = 0.0;
    for (int k = 0; k < n; k++) {
        double rx = x - X[k], ry = y - Y[k];
        double r = sqrt(rx * rx + ry * ry);
        double dw;
        double w = spline_weight(r / d[k], grad ? &dw : NULL, NULL);
        phi[k] = w;
        if (w > 0.0) {
            active++;
            if (d[k] > s)
                s = d[k];
        }
        if (grad) {
            /* dw/dx = w'(q) (x - X_k) / (r d_k); w'(0) = 0 at r = 0 */
            double g = (w > 0.0 && r > 0.0) ? dw / (r * d[k]) : 0.0;
            dphix[k] = g * rx;
            dphiy[k] = g * ry;
        }
    }
    if (active < 3)
        return -1;

    /* The moment matrix A = sum_k p_k p_k^T w_k (eq. 15) and its
     * derivatives, with p_k = (1, (X_k - x)/s, (Y_k - y)/s). */
    double A[9] = {0}, Ax[9] = {0}, Ay[9] = {0};
    for (int k = 0; k < n; k++) {
        if (!(phi[k] > 0.0))
            continue;
        const double p[3] = {1.0, (X[k] - x) / s, (Y[k] - y) / s};
        add_outer(A, phi[k], p);
        if (grad) {
            add_outer(Ax, dphix[k], p);
            add_outer(Ay, dphiy[k], p);
        }
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
    double gamma[3] = {1.0, 0.0, 0.0};
    if (LAPACKE_dpotrs_work(LAPACK_COL_MAJOR, 'U', 3, 1, A, 3, gamma, 3) != 0)
        return -1;

    /* gamma_x, gamma_y = A^-1 (p_x - A_x gamma), A^-1 (p_y - A_y gamma):
     * two right-hand sides, the columns of G, with the same factor */
    double G[6] = {0};
    if (grad) {
        for (int i = 0; i < 3; i++) {
            G[i] = (i == 1 ? 1.0 / s : 0.0)
                   - (Ax[i] * gamma[0] + Ax[i + 3] * gamma[1] + Ax[i + 6] * gamma[2]);
            G[i + 3] = (i == 2 ? 1.0 / s : 0.0)
                       - (Ay[i] * gamma[0] + Ay[i + 3] * gamma[1] + Ay[i + 6] * gamma[2]);
        }
        if (LAPACKE_dpotrs_work(LAPACK_COL_MAJOR, 'U', 3, 2, A, 3, G, 3) != 0)
            return -1;
    }

    /* Phi_k = gamma . p_k w_k (eq. 14) and its gradient */
    for (int k = 0; k < n; k++) {
        double w = phi[k];
        if (!(w > 0.0)) {
            phi[k] = 0.0;
            if (grad)
                dphix[k] = dphiy[k] = 0.0;
            continue;
        }
        const double p[3] = {1.0, (X[k] - x) / s, (Y[k] - y) / s};
        double gp = dot3(gamma, p);
        phi[k] = gp * w;
        if (grad) {
            dphix[k] = dot3(G, p) * w + gp * dphix[k];
            dphiy[k] = dot3(G + 3, p) * w + gp * dphiy[k];
        }
    }
    return 0;
}
