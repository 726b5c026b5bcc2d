/**
 * @file step.c
 * @brief One MPM time step: the paper's Tasks 0-8 in order, with the
 *        stages' subscribers at the seams the paper names.
 */
#include "step.h"

/// [assign_fields]
int assign_fields(Sim *sim)
{
    if (sim->hooks.seam[SEAM_TASK1_FIELDS].n == 0)
        return 0;
    fields_begin_step(sim);
    if (hooks_run_step(sim, SEAM_TASK1_FIELDS) || fields_resolve(sim))
        return -1;
    stencils_fields(sim);               /* the stored stencils' slots */
    return 0;
}
/// [assign_fields]

/// [sim_step]
int sim_step(Sim *sim)
{
    const UpdateScheme *us = sim->scene.run.scheme;
    double dt = sim->dt;

    grid_clear(&sim->grid, sim->threads);         /* Task 8 of the last step */
    locate_points(sim);                           /* Task 0 */
    if (assign_fields(sim))                       /* Task 1: v(p,i) */
        return -1;
    extrapolate(sim, EXTRAP_MASS | (us->before > 0 ? 0u : EXTRAP_FORCE));

    grid_velocities(sim);                         /* Task 2 */
    if (us->before > 0) {                         /* USF (and USAVG) */
        if (grid_contact(sim, SEAM_TASK2_HELD))   /* the last step's contact */
            return -1;
        grid_prescribe(sim, SEAM_TASK2_HELD);
        if (update_stress(sim, us->before * dt))
            return -1;
        extrapolate(sim, EXTRAP_FORCE);           /* Task 3 */
    }
    if (grid_contact(sim, SEAM_TASK2_CONTACT))    /* what the update starts from */
        return -1;
    grid_prescribe(sim, SEAM_TASK2_CONTACT);      /* moving boundaries */

    grid_momentum_update(sim);                    /* Tasks 3-4 */
    if (grid_contact(sim, SEAM_TASK4_CONTACT))
        return -1;
    grid_prescribe(sim, SEAM_TASK4_CONTACT);

    if (update_points(sim))                       /* Task 5 */
        return -1;

    if (us->after > 0) {                          /* Task 6 */
        if (us->reextrapolate) {                  /* 6c: MUSL (and USAVG) */
            double *const p[] = { sim->grid.px, sim->grid.py };
            grid_zero(&sim->grid, p, 2, sim->threads);
            extrapolate(sim, EXTRAP_MOMENTUM);    /* eq. 31: old S, new v */
            grid_velocities(sim);
            if (grid_contact(sim, SEAM_TASK6_CONTACT))
                return -1;
            grid_prescribe(sim, SEAM_TASK6_CONTACT);
        }
        if (update_stress(sim, us->after * dt))   /* 6a: USL uses Task 4 */
            return -1;
    }

    if (hooks_run_step(sim, SEAM_TASK7))          /* Task 7: move cracks */
        return -1;
    sim->t += dt;
    sim->step++;
    return 0;
}
/// [sim_step]

int sim_advance(Sim *sim)
{
    return sim->scene.run.method->step(sim);
}
