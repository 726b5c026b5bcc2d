/**
 * @file energy_balance.c
 * @brief Energy in = energy stored + dissipated + error, per run.
 */
#include "checkpoint.h"
#include "energy_guard.h"
#include "energy_balance.h"

#include <stdlib.h>
#include <string.h>

#include "step.h"

/// [energy_balance_in]
/** SEAM_ENERGY_IN: the energy put in so far, the start's and the work of
 *  gravity and loads (for the energy guard, energy_guard.h). */
static double energy_balance_in(const Sim *sim, void *state, const char **name)
{
    (void)sim;
    const EnergyBalance *B = state;
    *name = "energy in";
    return B->e0 + B->w_ext;
}
/// [energy_balance_in]

static void energy_balance_release(void *state)
{
    EnergyBalance *B = state;
    free(B->x);
    free(B->y);
    free(B);
}

/// [energy_balance_prepare]
int energy_balance_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    (void)state;
    const Scene *sc = &sim->scene;
    unsigned needs = SEAM_BIT(SEAM_TASK4_CONTACT) | SEAM_BIT(SEAM_TASK7);
    if (sc->run.method && (sc->run.method->seams & needs) != needs)
        return 0;           /* the account follows the step through its
                               seams: a method without them keeps its own */
    EnergyBalance *B = calloc(1, sizeof *B);
    if (!B || sim_attach(sim, "energy balance", B, energy_balance_release)) {
        free(B);
        snprintf(err, errlen, "%s: out of memory (energy balance)", sc->file);
        return -1;
    }
    Totals t = sim_totals(sim);
    B->e0 = t.kinetic + t.strain;
    int n = sim->pts.n;
    int per_step = sc->run.gx != 0.0 || sc->run.gy != 0.0 || sc->nloads > 0;
    if (sc->run.damping > 0.0 &&                 /* the Task-4 seam needs q */
        (grid_want(&sim->grid, &sim->grid.qx) || grid_want(&sim->grid, &sim->grid.qy) ||
         hooks_on_step(&sim->hooks, SEAM_TASK4_CONTACT, energy_balance_damping, B))) {
        snprintf(err, errlen, "%s: too many step hooks", sc->file);
        return -1;
    }
    if (per_step) {
        B->x = malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
        B->y = malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
        if (!B->x || !B->y ||
            hooks_on_step(&sim->hooks, SEAM_TASK7, energy_balance_step, B)) {
            snprintf(err, errlen, "%s: out of memory (energy balance)", sc->file);
            return -1;
        }
        memcpy(B->x, sim->pts.x, (size_t)n * sizeof(double));
        memcpy(B->y, sim->pts.y, (size_t)n * sizeof(double));
    }
    if (per_step && !energy_guard_moving(sc, NULL, 0) &&       /* the energy guard's measure */
        hooks_on_energy_in(&sim->hooks, energy_balance_in, B)) {
        snprintf(err, errlen, "%s: too many energy hooks", sc->file);
        return -1;
    }
    if (hooks_on_report(&sim->hooks, energy_balance_report, B) ||
        hooks_on_checkpoint(&sim->hooks, energy_balance_checkpoint, B)) {
        snprintf(err, errlen, "%s: too many report hooks", sc->file);
        return -1;
    }
    return 0;
}
/// [energy_balance_prepare]

/// [energy_balance_step]
int energy_balance_step(Sim *sim, void *state, Seam seam)
{
    (void)seam;
    EnergyBalance *B = state;
    const Particles *P = &sim->pts;
    const RunSettings *run = &sim->scene.run;
    double dt = sim->dt, wg = 0, wl = 0;
    double gs = gravity_scale(run, sim->t + 0.5 * dt);  /* as the step used */
    const Scene *sc = &sim->scene;
    for (int l = 0; l < sc->nloads; l++) {          /* before B->x moves on */
        const Load *L = &sc->loads[l];
        if (L->count == 0)
            continue;
        double fx, fy;
        load_point_force(L, sim->t, &fx, &fy);
        for (int k = 0; k < L->count; k++) {
            int p = L->points[k];
            wl += fx * (P->x[p] - B->x[p]) + fy * (P->y[p] - B->y[p]);
        }
    }
    if (run->gx != 0.0 || run->gy != 0.0) {
        for (int p = 0; p < P->n; p++) {
            double ux = P->x[p] - B->x[p], uy = P->y[p] - B->y[p];
            wg += P->m[p] * (run->gx * gs * ux + run->gy * gs * uy);
            B->x[p] = P->x[p];
            B->y[p] = P->y[p];
        }
    } else {        /* no gravity: wg is +0 (a sum of zeros from +0), and */
        for (int l = 0; l < sc->nloads; l++)        /* only the loaded */
            for (int k = 0; k < sc->loads[l].count; k++) {  /* points' */
                int p = sc->loads[l].points[k];     /* places are read */
                B->x[p] = P->x[p];
                B->y[p] = P->y[p];
            }
    }
    B->w_ext += wg + wl;
    return 0;
}
/// [energy_balance_step]

/// [energy_balance_damping]
int energy_balance_damping(Sim *sim, void *state, Seam seam)
{
    (void)seam;
    EnergyBalance *B = state;
    const Grid *g = &sim->grid;
    double dt = sim->dt, w = 0;
    for (int s = 0; s < g->nslots; s++) {
        double m = g->m[s];
        if (m <= 0.0)
            continue;
        /* eq. 4: the force -kappa p_i (p_i of Task 3 = p - dt f) times
           the mean of the node's velocities before and after Task 4 */
        double px = g->px[s] - dt * g->fx[s], py = g->py[s] - dt * g->fy[s];
        w += (px * (px + 0.5 * dt * g->fx[s]) + py * (py + 0.5 * dt * g->fy[s])) / m;
    }
    B->w_damp += dt * sim->scene.run.damping * w;
    return 0;
}
/// [energy_balance_damping]

EnergyTerms energy_balance_terms(const Sim *sim, const EnergyBalance *B)
{
    Totals t = sim_totals(sim);
    EnergyTerms e;
    e.in = B->e0 + B->w_ext;
    e.stored = t.kinetic + t.strain;
    e.damping = B->w_damp;
    e.dissipated = energy_seam_dissipated(sim);
    e.error = e.in - e.stored - e.damping - e.dissipated;
    return e;
}

double energy_seam_dissipated(const Sim *sim)
{
    double d = 0;                              /* every stage's, by the seam */
    const SeamList *l = &sim->hooks.seam[SEAM_ENERGY];
    for (int k = 0; k < l->n; k++) {
        const char *name;
        d += l->at[k].fn.energy(sim, l->at[k].state, &name);
    }
    return d;
}

/// [energy_balance_report]
int energy_balance_report(const Sim *sim, void *state, FILE *f)
{
    const EnergyBalance *B = state;
    EnergyTerms e = energy_balance_terms(sim, B);
    return energy_terms_print(sim, &e, B->e0, energy_guard_moving(&sim->scene, NULL, 0), f);
}

int energy_terms_print(const Sim *sim, const EnergyTerms *e, double e0,
                       int moving, FILE *f)
{
    double scale = e->in != 0.0 ? e->in : 1.0;
    const Units *u = sim->scene.run.units;
    int bad = fprintf(f, "mpm: energy (%s) at t = %.6g %s: in %.9g (start %.9g, "
                      "external work %.9g) = stored %.9g + damping %.9g", u->energy,
                      sim->t, u->time, e->in, e0, e->in - e0, e->stored,
                      e->damping) < 0;
    const SeamList *l = &sim->hooks.seam[SEAM_ENERGY];  /* each stage's term */
    for (int k = 0; k < l->n; k++) {
        const char *name;
        double w = l->at[k].fn.energy(sim, l->at[k].state, &name);
        bad |= fprintf(f, " + %s %.9g", name, w) < 0;
    }
    if (moving)             /* no balance: say so, not a percentage */
        bad |= fprintf(f, " + not counted %.9g: the work of %d moving "
                       "boundar%s or held point set%s, which this account "
                       "does not measure (no balance)\n", e->error, moving,
                       moving == 1 ? "y" : "ies", moving == 1 ? "" : "s") < 0;
    else
        bad |= fprintf(f, " + error %.9g (%+.4f %% of in)\n", e->error,
                       100.0 * e->error / scale) < 0;
    return bad ? -1 : 0;
}
/// [energy_balance_report]

int energy_balance_install(Hooks *h)
{
    return hooks_on_prepare(h, energy_balance_prepare, NULL);
}

int energy_balance_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    EnergyBalance *B = state;
    if (checkpoint_io(f, &B->e0, sizeof B->e0, save) ||
        checkpoint_io(f, &B->w_ext, sizeof B->w_ext, save) ||
        checkpoint_io(f, &B->w_damp, sizeof B->w_damp, save))
        return -1;
    if (!save && B->x) {               /* Task 7 left them equal to the points' */
        memcpy(B->x, sim->pts.x, (size_t)sim->pts.n * sizeof(double));
        memcpy(B->y, sim->pts.y, (size_t)sim->pts.n * sizeof(double));
    }
    return 0;
}
