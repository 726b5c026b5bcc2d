/*
 * Exercise 6.2, "MLS gradients" (chapter 6): the gradients of the moving
 * least-squares shape functions (eq. 14-16), from the factored moment
 * matrix that mls_fit() made at the same place.  Copy this file, fill in
 * mls_gradient(), and run
 *     make exercise EX=6-xefg/mls-gradients SOLUTION=your_copy.c
 * The contract is in src/6-xefg/mls.h; README.md says what is checked.
 */
#include <lapacke.h>
#include <math.h>
#include <stddef.h>

#include "mls.h"
#include "spline.h"

int mls_gradient(double x, double y, int n, const double *X, const double *Y,
                 const double *d, const MlsFit *fit, double *dphix, double *dphiy)
{
    /* TODO: grad w_k (chain rule through spline_weight), A_x and A_y,
     * gamma_x = A^-1 (p_x - A_x gamma) with fit->U, and
     * dPhi_k/dx = gamma_x . p_k w_k + gamma . p_k dw_k/dx (the same in y).
     * This stub returns zero gradients: a displacement field would have
     * no strain, and the tests fail until you write them. */
    (void)x;
    (void)y;
    (void)X;
    (void)Y;
    (void)d;
    (void)fit;
    for (int k = 0; k < n; k++)
        dphix[k] = dphiy[k] = 0.0;
    return 0;
}
