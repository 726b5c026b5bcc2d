/**
 * @file energy_guard.c
 * @brief The energy guard (energy_guard.h).
 */
#include "energy_guard.h"

#include <math.h>
#include <stdio.h>

#include "step.h"

int energy_guard_moving(const Scene *sc, char *first, size_t len)
{
    int n = 0;
    for (int b = 0; b < sc->nbc; b++)
        if (sc->bc[b].moving && n++ == 0 && first)
            snprintf(first, len, "moving boundary %d", b);
    for (int h = 0; h < sc->nheld; h++) {
        const Hold *H = &sc->held[h].hold;      /* a table counts as moving */
        if ((H->vx != 0.0 || H->vy != 0.0 || H->nrows > 0) && n++ == 0 && first)
            snprintf(first, len, "point_velocities %d", h);
    }
    return n;
}

int energy_guard_open(const Scene *sc, char *why, size_t len)
{
    if (energy_guard_moving(sc, why, len))
        return 2;
    if (sc->run.gx != 0.0 || sc->run.gy != 0.0) {
        snprintf(why, len, "gravity");
        return 1;
    }
    for (int l = 0; l < sc->nloads; l++)
        if (sc->loads[l].fx != 0.0 || sc->loads[l].fy != 0.0) {
            snprintf(why, len, "load %d", l);
            return 1;
        }
    return 0;
}

int energy_guard_check(const Sim *sim, const config_t *cfg, SceneReader *r)
{
    const config_setting_t *e = config_lookup(cfg, "run.energy_limit");
    char why[64];
    int open = energy_guard_open(&sim->scene, why, sizeof why);
    if (!e || sim->scene.run.energy_limit == 0 || open == 0 ||
        (open == 1 && sim->hooks.seam[SEAM_ENERGY_IN].n > 0))
        return 0;
    return scene_error(r, e, "energy_limit", "%g: %s does work on this scene "
                       "that %s, so the energy guard has nothing to compare "
                       "the energy with; leave energy_limit out or set 0",
                       sim->scene.run.energy_limit, why, open == 2 ?
                       "no stage counts" : "this run does not count (chapter "
                       "5's energy account counts gravity and loads, under "
                       "run.method \"mpm\")");
}

EnergyGuard energy_guard_start(const Sim *sim)
{
    char why[64];
    Totals t = sim_totals(sim);
    EnergyGuard g = {sim->scene.run.energy_limit, t.kinetic + t.strain, 0};
    int open = energy_guard_open(&sim->scene, why, sizeof why);
    g.counted = open == 1 && sim->hooks.seam[SEAM_ENERGY_IN].n > 0;
    if (!isfinite(g.e_start) || (open && !g.counted) || (!open && !(g.e_start > 0)))
        g.limit = 0;
    return g;
}

int energy_guard_passed(Sim *sim, const EnergyGuard *g, double stored)
{
    if (g->limit == 0)
        return 0;
    const char *name;
    const Subscriber *s = &sim->hooks.seam[SEAM_ENERGY_IN].at[0];
    double in = g->counted ? s->fn.energy(sim, s->state, &name) : g->e_start;
    if (!(in > 0) || !(stored > g->limit * in))
        return 0;
    step_fail(sim, -1, g->counted ?
              "energy (kinetic + strain) / the energy put in (start and "
              "external work), above run.energy_limit (it cannot pass what "
              "was put in)" :
              "energy (kinetic + strain) / its start, above run.energy_limit "
              "(a closed scene's energy cannot grow)", stored / in);
    return 1;
}
