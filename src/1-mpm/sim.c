/**
 * @file sim.c
 * @brief A simulation's stage states, its totals, and its release (the
 *        loading of a scene into it is the base floor's: scene_load.c).
 */
#include "sim.h"

#include <stdlib.h>
#include <string.h>

void sim_init(Sim *sim)
{
    memset(sim, 0, sizeof *sim);
    sim->scene.run.units = units_default();
}

int sim_attach(Sim *sim, const char *name, void *state,
               void (*release)(void *state))
{
    if (sim->next == SIM_MAX_EXT)
        return -1;
    sim->ext[sim->next++] = (SimExt){name, state, release};
    return 0;
}

void *sim_state(const Sim *sim, const char *name)
{
    for (int k = 0; k < sim->next; k++)
        if (strcmp(sim->ext[k].name, name) == 0)
            return sim->ext[k].state;
    return NULL;
}

/// [sim_totals]
Totals sim_totals(const Sim *sim)
{
    const Particles *P = &sim->pts;
    Totals t = {0, 0, 0, 0};
    for (int p = 0; p < P->n; p++) {
        double m = P->m[p];
        t.kinetic += 0.5 * m * (P->vx[p] * P->vx[p] + P->vy[p] * P->vy[p]);
        t.strain += P->vol[p] * material_energy_density(P->sxx[p], P->syy[p],
                        P->sxy[p], P->exx[p], P->eyy[p], P->exy[p]);
        t.px += m * P->vx[p];
        t.py += m * P->vy[p];
    }
    return t;
}
/// [sim_totals]

void sim_free(Sim *sim)
{
    for (int k = sim->next - 1; k >= 0; k--)
        if (sim->ext[k].release)
            sim->ext[k].release(sim->ext[k].state);
    sim->next = 0;
    fields_free(&sim->fields);
    strips_free(&sim->strips);
    stencils_free(&sim->stencils);
    particles_free(&sim->pts);
    grid_free(&sim->grid);
    scene_free(&sim->scene);
    free(sim->bodyke);
    sim->bodyke = NULL;
    free(sim->moving);
    free(sim->moving_bc);
    sim->moving = sim->moving_bc = NULL;
    sim->nmoving = 0;
}
