/**
 * @file time_step.c
 * @brief The time step: the fastest wave, carried by the fastest point,
 *        may cross a cell in no less than a step (times run.cfl), unless
 *        the method has its own rule; and its checks.
 */
#include <math.h>
#include <stdio.h>

#include "sim.h"

/// [sim_set_time_step]
void sim_set_time_step(Sim *sim)
{
    const Scene *sc = &sim->scene;
    const Particles *P = &sim->pts;
    double c = 0.0, v2 = 0.0;
    for (int k = 0; k < sc->nmat; k++)
        c = fmax(c, sc->mat[k].wave);
    for (int p = 0; p < P->n; p++)
        v2 = fmax(v2, P->vx[p] * P->vx[p] + P->vy[p] * P->vy[p]);
    const Method *method = sc->run.method;
    if (method && method->stable_step)          /* the method's own rule */
        sim->dt = sc->run.cfl * method->stable_step(sim);
    else    /* the fastest wave, carried by the fastest point, crosses a cell */
        sim->dt = sc->run.cfl * fmin(sc->dx, sc->dy) / (c + sqrt(v2));
    double steps = ceil(sc->run.time / sim->dt - 1e-9);
    /* 0: no step, or more than a long holds (sim_check_time_step says) */
    sim->nsteps = steps >= 1.0 && steps < 4e18 ? (long)steps : 0;
}
/// [sim_set_time_step]

int sim_check_time_step(const Sim *sim, char *err, size_t errlen)
{
    const Scene *sc = &sim->scene;
    const RunSettings *run = &sc->run;
    const char *tu = run->units->time;
    int fast = 0;                                /* the fastest material */
    for (int k = 1; k < sc->nmat; k++)
        if (sc->mat[k].wave > sc->mat[fast].wave)
            fast = k;
    double c = sc->mat[fast].wave, h = fmin(sc->dx, sc->dy);
    if (!(isfinite(c) && c > 0)) {
        snprintf(err, errlen, "%s: material \"%s\": wave speed sqrt(c11 / rho) = %g "
                 "(E %g, rho %g) gives no time step", sc->file, sc->mat[fast].name,
                 c, sc->mat[fast].E, sc->mat[fast].rho);
        return -1;
    }
    if (!(isfinite(sim->dt) && sim->dt > 0)) {
        snprintf(err, errlen, "%s: run.cfl %g x cell %g / (wave speed %g + the "
                 "fastest point) gives a time step of %g %s", sc->file, run->cfl,
                 h, c, sim->dt, tu);
        return -1;
    }
    if (sim->nsteps == 0) {
        double steps = ceil(run->time / sim->dt - 1e-9);
        snprintf(err, errlen, "%s: run.time %g %s over time steps of %g %s (run.cfl "
                 "%g, cell %g, fastest wave %g in material \"%s\") is %s", sc->file,
                 run->time, tu, sim->dt, tu, run->cfl, h, c, sc->mat[fast].name,
                 steps < 1.0 ? "not one step" : "more steps than a run can count");
        return -1;
    }
    return 0;
}
