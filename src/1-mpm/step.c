/**
 * @file step.c
 * @brief One MPM time step: the paper's Tasks 0-8 in order, with the
 *        stages' hooks at the seams the paper names.
 */
#include <string.h>

#include "step.h"

/// [sim_step]
int sim_step(Sim *sim)
{
    const UpdateScheme *us = sim->scene.run.scheme;
    Hooks *h = &sim->hooks;
    double dt = sim->dt;

    grid_clear(&sim->grid);                       /* Task 8 of the last step */
    locate_points(sim);                           /* Task 0 */
    if (h->assign_fields && h->assign_fields(sim))
        return -1;                                /* Task 1: v(p,i) */
    extrapolate(sim, EXTRAP_MASS | (us->before > 0 ? 0u : EXTRAP_FORCE));

    grid_velocities(sim);                         /* Task 2 */
    if (h->contact && h->contact(sim, 2))
        return -1;
    if (us->before > 0) {                         /* USF (and USAVG) */
        if (update_stress(sim, us->before * dt))
            return -1;
        extrapolate(sim, EXTRAP_FORCE);           /* Task 3 */
    }

    grid_momentum_update(sim);                    /* Tasks 3-4 */
    if (h->contact && h->contact(sim, 4))
        return -1;

    if (update_points(sim))                       /* Task 5 */
        return -1;

    if (us->after > 0) {                          /* Task 6 */
        if (us->reextrapolate) {                  /* 6c: MUSL (and USAVG) */
            memset(sim->grid.px, 0, (size_t)sim->grid.nslots * sizeof(double));
            memset(sim->grid.py, 0, (size_t)sim->grid.nslots * sizeof(double));
            extrapolate(sim, EXTRAP_MOMENTUM);    /* eq. 31: old S, new v */
            grid_velocities(sim);
            if (h->contact && h->contact(sim, 6))
                return -1;
        }
        if (update_stress(sim, us->after * dt))   /* 6a: USL uses Task 4 */
            return -1;
    }

    if (h->move_cracks && h->move_cracks(sim))
        return -1;                                /* Task 7 */
    sim->t += dt;
    sim->step++;
    return 0;
}
/// [sim_step]
