/**
 * @file mls_gradient.c
 * @brief The gradients of the MLS shape functions (eq. 14-16), from the
 *        factored moment matrix that mls.c built at the same place.
 *
 * Differentiating A gamma = p with the basis origin c and scale s held
 * fixed,
 *
 *   A gamma_x = p_x - A_x gamma,   dPhi_k/dx = gamma_x . p_k w_k + gamma . p_k w_k,x
 *
 * and only then c = x: p_x = (0, 1/s, 0), p_y = (0, 0, 1/s). One Cholesky
 * factor of A serves gamma (mls.c) and both derivatives (here).
 */
#include <lapacke.h>
#include <math.h>
#include <stddef.h>

#include "mls.h"
#include "spline.h"

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

int mls_gradient(double x, double y, int n, const double *X, const double *Y,
                 const double *d, const MlsFit *fit, double *dphix, double *dphiy)
{
    const double s = fit->s, *gamma = fit->gamma;

    /* The gradients of the weights, dw/dx = w'(q) (x - X_k) / (r d_k)
     * (w'(0) = 0 at r = 0), and those of the moment matrix,
     * A_x = sum_k p_k p_k^T dw_k/dx. */
    double Ax[9] = {0}, Ay[9] = {0};
    for (int k = 0; k < n; k++) {
        double rx = x - X[k], ry = y - Y[k];
        double r = sqrt(rx * rx + ry * ry);
        double dw;
        double w = spline_weight(r / d[k], &dw, NULL);
        if (!(w > 0.0)) {
            dphix[k] = dphiy[k] = 0.0;
            continue;
        }
        double g = r > 0.0 ? dw / (r * d[k]) : 0.0;
        dphix[k] = g * rx;
        dphiy[k] = g * ry;
        const double p[3] = {1.0, (X[k] - x) / s, (Y[k] - y) / s};
        add_outer(Ax, dphix[k], p);
        add_outer(Ay, dphiy[k], p);
    }

    /* gamma_x, gamma_y = A^-1 (p_x - A_x gamma), A^-1 (p_y - A_y gamma):
     * two right-hand sides, the columns of G, with mls.c's factor */
    double G[6];
    for (int i = 0; i < 3; i++) {
        G[i] = (i == 1 ? 1.0 / s : 0.0)
               - (Ax[i] * gamma[0] + Ax[i + 3] * gamma[1] + Ax[i + 6] * gamma[2]);
        G[i + 3] = (i == 2 ? 1.0 / s : 0.0)
                   - (Ay[i] * gamma[0] + Ay[i + 3] * gamma[1] + Ay[i + 6] * gamma[2]);
    }
    if (LAPACKE_dpotrs_work(LAPACK_COL_MAJOR, 'U', 3, 2, fit->U, 3, G, 3) != 0)
        return -1;

    /* dPhi_k = grad gamma . p_k w_k + gamma . p_k grad w_k (eq. 14) */
    for (int k = 0; k < n; k++) {
        double rx = x - X[k], ry = y - Y[k];
        double w = spline_weight(sqrt(rx * rx + ry * ry) / d[k], NULL, NULL);
        if (!(w > 0.0))
            continue;                       /* dPhi_k = 0, set above */
        const double p[3] = {1.0, (X[k] - x) / s, (Y[k] - y) / s};
        double gp = dot3(gamma, p);
        dphix[k] = dot3(G, p) * w + gp * dphix[k];
        dphiy[k] = dot3(G + 3, p) * w + gp * dphiy[k];
    }
    return 0;
}
