/**
 * @file stable_step.c
 * @brief The critical time step of the central-difference scheme,
 *        2 / omega_max, with omega_max^2 the largest eigenvalue of
 *        M_L^-1 K found by power iteration (xefg.md section 2.5: the h / c
 *        rule is not reliable for MLS supports with enrichment).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cohesive.h"
#include "xefg.h"

/** Most iterations. */
#define POWER_MAX 300
/** The relative change of omega^2 that ends them. */
#define POWER_TOL 1e-6

int xefg_power_iteration(Xefg *x, const Sim *sim)
{
    size_t n2 = 2 * (size_t)x->ndof;
    double *z = malloc(sizeof(double) * n2), *kz = malloc(sizeof(double) * n2);
    double *gs = malloc(3 * sizeof(double) * (size_t)x->ngauss);
    int rc = z && kz && gs ? xefg_power_iteration_in(x, sim, z, kz, gs) : -1;
    free(z), free(kz), free(gs);
    return rc;
}

/// [xefg_power_iteration]
int xefg_power_iteration_in(Xefg *x, const Sim *sim, double *z, double *kz,
                            double *gs)
{
    size_t n2 = 2 * (size_t)x->ndof;
    uint64_t s = 12345u;                      /* a fixed start */
    for (size_t k = 0; k < n2; k++) {
        s = s * 6364136223846793005u + 1442695040888963407u;
        z[k] = (double)(s >> 11) / 9007199254740992.0 - 0.5;
    }
    double lambda = 0.0;
    int it;
    for (it = 1; it <= POWER_MAX; it++) {
        double zmz = 0.0;                           /* z^T M z = 1 */
        for (size_t k = 0; k < n2; k++)
            zmz += x->mass[k / 2] * z[k] * z[k];
        double scale = 1.0 / sqrt(zmz);
        for (size_t k = 0; k < n2; k++)
            z[k] *= scale;
        memset(gs, 0, 3 * sizeof(double) * (size_t)x->ngauss);
        xefg_strain_update(x, sim, z, gs, NULL);    /* sigma = C eps(z) */
        xefg_internal_force(x, gs, kz);             /* K z */
        if (x->coh)                                 /* the penalty's K */
            cohesive_stiffness(x->coh, z, kz);
        double zkz = 0.0;
        for (size_t k = 0; k < n2; k++)
            zkz += z[k] * kz[k];                    /* Rayleigh quotient */
        for (size_t k = 0; k < n2; k++)
            z[k] = kz[k] / x->mass[k / 2];          /* M^-1 K z */
        int done = fabs(zkz - lambda) <= POWER_TOL * zkz;
        lambda = zkz;
        if (done)
            break;
    }
    x->power_iterations = it > POWER_MAX ? POWER_MAX : it;
    x->omega_max = sqrt(lambda);
    x->stable_step = 2.0 / x->omega_max;
    return isfinite(x->stable_step) && x->stable_step > 0.0 ? 0 : -1;
}
/// [xefg_power_iteration]
