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

/** The disk with the overrides @p over run to its end, step by step, with
 *  @p measure (spin_measure() or a stage's own): the end in *@p end and
 *  the ratios to the start in *@p ratio when it ran through; the steps
 *  taken and the run's steps in @p steps, and the sim's failure record
 *  (filled when a step failed) in *@p fail. @return 0, or the step's
 *  non-zero status. */
static inline int spin_turn(const char *const over[], Spin (*measure)(const Sim *),
                            Spin *end, Spin *ratio, long steps[2], Failure *fail)
{
    Sim *sim = tk_load_file("tests/1-mpm/scenes/spinning_disk.cfg", over);
    Spin start = measure(sim);
    long k = 0;
    int rc = 0;
    while (k < sim->nsteps && (rc = sim_advance(sim)) == 0)
        k++;
    if (rc == 0) {
        *end = measure(sim);
        ratio->ke = end->ke / start.ke;
        ratio->lz = end->lz / start.lz;
    }
    steps[0] = k;
    steps[1] = sim->nsteps;
    *fail = sim->fail;
    tk_free(sim);
    return rc;
}

#endif
