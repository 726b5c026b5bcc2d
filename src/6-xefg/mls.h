/**
 * @file mls.h
 * @brief Moving least-squares shape functions with a linear basis (eq. 13-16).
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

#endif
