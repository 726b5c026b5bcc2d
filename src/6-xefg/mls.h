/**
 * @file mls.h
 * @brief Moving least-squares shape functions with a linear basis (eq. 13-16):
 *        the moment matrix and the values (mls.c), their gradients
 *        (mls_gradient.c).
 */
#ifndef MPM_MLS_H
#define MPM_MLS_H

/// [mls_shape]
/**
 * @brief The MLS shape functions at (x, y) of @p n nodes (X[k], Y[k]) with
 *        support radii d[k], and their gradients.
 *
 * Phi_k(x) = p^T(x) A^-1(x) p(X_k) w_k(x), A = sum_k p(X_k) p^T(X_k) w_k,
 * p = (1, X, Y), w_k = spline_weight(|x - X_k| / d_k). The basis is
 * shifted to (x, y) and scaled by the largest radius (xefg.md pitfall 1),
 * which leaves Phi unchanged and keeps A well conditioned far from the
 * origin.
 * @param x     the place x
 * @param y     the place y
 * @param n     number of nodes
 * @param X     node x (n values)
 * @param Y     node y (n values)
 * @param d     support radii (n values)
 * @param phi   n values (not NULL)
 * @param dphix n values of dPhi/dx (NULL: not wanted; then dphiy too)
 * @param dphiy n values of dPhi/dy
 * @return 0; -1 when fewer than three of the nodes have w > 0 or they lie
 *         on a line (the moment matrix A is singular), phi then undefined.
 */
int mls_shape(double x, double y, int n, const double *X, const double *Y,
              const double *d, double *phi, double *dphix, double *dphiy);
/// [mls_shape]

/// [mls_fit]
/** The moment matrix of one place, factored, and what its shape functions
 *  and their gradients are made of (eq. 14-15), in the basis
 *  p(z) = (1, (z_x - x)/s, (z_y - y)/s) shifted to the place (x, y). */
typedef struct MlsFit {
    double s;         /**< the basis' length: the largest radius d_k of the
                           nodes with w_k > 0 */
    double U[9];      /**< Cholesky factor of A = sum_k w_k p_k p_k^T: A =
                           U^T U, U upper triangular, 3 x 3 column major
                           (LAPACKE_dpotrf 'U'; ready for LAPACKE_dpotrs) */
    double gamma[3];  /**< A^-1 p(x), p(x) = (1, 0, 0): Phi_k = gamma . p_k w_k */
} MlsFit;

/**
 * @brief The weights of the nodes at (x, y) and the factored moment matrix
 *        there (eq. 15-16): the first half of mls_shape().
 * @param x, y, n, X, Y, d as in mls_shape()
 * @param w    n values: w_k = spline_weight(|x - X_k| / d_k) (0 outside
 *             the support)
 * @param fit  the scale, the factor of A and gamma
 * @return 0; -1 when fewer than three nodes have w > 0 or A is singular or
 *         nearly so (reciprocal condition number below 1e-12: nodes on a
 *         line).
 */
int mls_fit(double x, double y, int n, const double *X, const double *Y,
            const double *d, double *w, MlsFit *fit);
/// [mls_fit]

/// [mls_gradient]
/**
 * @brief The gradients of the MLS shape functions at (x, y), from the fit
 *        mls_fit() made there: differentiate A gamma = p (eq. 14).
 *
 * With the basis origin held fixed while differentiating, p_x = (0, 1/s, 0)
 * and p_y = (0, 0, 1/s); A_x = sum_k (dw_k/dx) p_k p_k^T, and
 *   A gamma_x = p_x - A_x gamma,
 *   dPhi_k/dx = gamma_x . p_k w_k + gamma . p_k dw_k/dx,
 * the same in y.
 * @param x, y, n, X, Y, d as in mls_shape()
 * @param fit   what mls_fit() returned for the same place and nodes
 * @param dphix n values of dPhi_k/dx (0 for a node with w_k = 0)
 * @param dphiy n values of dPhi_k/dy
 * @return 0; -1 when the solve fails.
 */
int mls_gradient(double x, double y, int n, const double *X, const double *Y,
                 const double *d, const MlsFit *fit, double *dphix, double *dphiy);
/// [mls_gradient]

#endif
