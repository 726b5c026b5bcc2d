/**
 * @file spin.h
 * @brief The spinning disk of tests/1-mpm/scenes/spinning_disk.cfg (stages
 *        1 and 8): its density, spin and radius, and what the tests
 *        measure of it.
 */
#ifndef MPM_TEST_SPIN_H
#define MPM_TEST_SPIN_H

#include <math.h>
#include <stdlib.h>

#include "testkit.h"

#define RHO 1.0e-3      /**< the disk's density (g/mm^3) */
#define W 1.048         /**< its spin (rad/ms) */
#define RADIUS 10.0     /**< its radius (mm) */

/** What a disk's points hold. */
typedef struct Spin {
    double ke;         /**< kinetic energy */
    double lz;         /**< angular momentum about (0, 0) */
    double vm_median;  /**< median von Mises stress / (rho v^2), v = W RADIUS */
    double vm_max;     /**< largest von Mises stress / (rho v^2) */
} Spin;

/** qsort() order of doubles. */
static inline int spin_by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/** The kinetic energy, angular momentum and von Mises stresses of the
 *  points of @p sim. */
static inline Spin spin_measure(const Sim *sim)
{
    const Particles *P = &sim->pts;
    Spin s = {0, 0, 0, 0};
    double *vm = malloc(sizeof(double) * (size_t)P->n), v = W * RADIUS;
    assert_non_null(vm);
    for (int p = 0; p < P->n; p++) {
        s.ke += 0.5 * P->m[p] * (P->vx[p] * P->vx[p] + P->vy[p] * P->vy[p]);
        s.lz += P->m[p] * (P->x[p] * P->vy[p] - P->y[p] * P->vx[p]);
        double a = P->sxx[p], b = P->syy[p], c = P->sxy[p];
        vm[p] = sqrt(a * a - a * b + b * b + 3.0 * c * c) / (RHO * v * v);
    }
    qsort(vm, (size_t)P->n, sizeof(double), spin_by_value);
    s.vm_median = vm[P->n / 2];
    s.vm_max = vm[P->n - 1];
    free(vm);
    return s;
}

#endif
