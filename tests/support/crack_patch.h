/**
 * @file crack_patch.h
 * @brief The crack patch test (paper's section 3.1; stages 2 and 8): the
 *        full double cantilever beam with its crack against the half beam
 *        held by symmetry, step by step, quantity by quantity.
 */
#ifndef MPM_TEST_CRACK_PATCH_H
#define MPM_TEST_CRACK_PATCH_H

#include <math.h>
#include <stdio.h>

#include "testkit.h"

/** The quantities compared: x, y, vx, vy, the stress and the strain. */
#define PATCH_NQ 10

/** The largest difference of each quantity between the upper half of the
 *  full run and the half run over all steps, and the largest value it
 *  takes in the half run (the scale of its round-off). */
typedef struct Patch {
    double diff[PATCH_NQ];   /**< max |full - half| of each quantity */
    double scale[PATCH_NQ];  /**< max |half| of each quantity */
} Patch;

/** The names of the quantities, in Patch's order. */
static const char *const patch_name[PATCH_NQ] = {
    "x", "y", "vx", "vy", "sigma_xx", "sigma_yy", "sigma_xy", "eps_xx",
    "eps_yy", "eps_xy"};

/** Run @p full and @p half (same time step, the half body's points in the
 *  order of the full body's upper half) for @p steps steps, one at a
 *  time, and compare them after each. */
static inline Patch patch_compare(Sim *full, Sim *half, long steps)
{
    Patch r = {{0}, {0}};
    int n = half->pts.n, off = full->pts.n - n;
    assert_int_equal(full->pts.n, 2 * n);
    assert_true(full->dt == half->dt);
    /* the upper half of the full body is generated after the lower half,
       row by row, in the same order as the half body */
    for (int p = 0; p < n; p++) {
        assert_true(full->pts.x[off + p] == half->pts.x[p]);
        assert_true(full->pts.y[off + p] == half->pts.y[p]);
    }
    for (long s = 0; s < steps; s++) {
        tk_steps(full, 1);
        tk_steps(half, 1);
        const Particles *F = &full->pts, *H = &half->pts;
        const double *fa[PATCH_NQ] = {F->x, F->y, F->vx, F->vy, F->sxx,
                                      F->syy, F->sxy, F->exx, F->eyy, F->exy};
        const double *ha[PATCH_NQ] = {H->x, H->y, H->vx, H->vy, H->sxx,
                                      H->syy, H->sxy, H->exx, H->eyy, H->exy};
        for (int q = 0; q < PATCH_NQ; q++)
            for (int p = 0; p < n; p++) {
                r.diff[q] = fmax(r.diff[q], fabs(fa[q][off + p] - ha[q][p]));
                r.scale[q] = fmax(r.scale[q], fabs(ha[q][p]));
            }
    }
    return r;
}

/** Print one line per quantity: its difference, scale and their ratio. */
static inline void patch_print(const Patch *r)
{
    for (int q = 0; q < PATCH_NQ; q++)
        printf("%-9s max |full - half| = %.3g, largest value %.3g, ratio %.3g\n",
               patch_name[q], r->diff[q], r->scale[q], r->diff[q] / r->scale[q]);
}

#endif
