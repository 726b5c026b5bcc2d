/**
 * @file energy_guard.c
 * @brief The energy guard (energy_guard.h).
 */
#include "energy_guard.h"

#include <math.h>
#include <stdio.h>

int energy_guard_open(const Scene *sc, char *why, size_t len)
{
    if (sc->run.gx != 0.0 || sc->run.gy != 0.0) {
        snprintf(why, len, "gravity");
        return 1;
    }
    for (int l = 0; l < sc->nloads; l++)
        if (sc->loads[l].fx != 0.0 || sc->loads[l].fy != 0.0) {
            snprintf(why, len, "load %d", l);
            return 1;
        }
    for (int b = 0; b < sc->nbc; b++)
        if (sc->bc[b].moving) {
            snprintf(why, len, "moving boundary %d", b);
            return 1;
        }
    for (int h = 0; h < sc->nheld; h++) {
        const Hold *H = &sc->held[h].hold;
        if (H->vx != 0.0 || H->vy != 0.0) {   /* a table's largest */
            snprintf(why, len, "point_velocities %d", h);
            return 1;
        }
    }
    return 0;
}

double energy_guard_level(const Sim *sim, double *e_start)
{
    char why[64];
    double limit = sim->scene.run.energy_limit;
    Totals t = sim_totals(sim);
    *e_start = t.kinetic + t.strain;
    if (limit <= 0.0 || energy_guard_open(&sim->scene, why, sizeof why))
        return INFINITY;
    return *e_start > 0.0 && isfinite(*e_start) ? limit * *e_start : INFINITY;
}
