/**
 * @file cohesive_output.c
 * @brief What a cohesive crack adds to a run's outputs: history.csv
 *        columns (the law's stored and dissipated energy, the mean
 *        traction and largest opening, the work of the held places), the
 *        end-of-run energy balance, the checkpoint of the history
 *        variables, and the dissipation through SEAM_ENERGY.
 */
#include <math.h>

#include "checkpoint.h"
#include "cohesive.h"

/** The mean normal traction over the cohesive points and the largest
 *  normal opening. */
static void crack_means(const Cohesive *c, double *t, double *open)
{
    double w = 0.0, s = 0.0, m = 0.0;
    for (int p = 0; p < c->npt; p++) {
        w += c->w[p];
        s += c->w[p] * c->tn[p];
        m = fmax(m, c->dn[p]);
    }
    *t = w > 0.0 ? s / w : 0.0;
    *open = m;
}

/// [cohesive_history]
/** history.csv: cohesive_stored and cohesive_dissipated (energy),
 *  cohesive_traction (the mean normal traction), cohesive_opening (the
 *  largest normal opening) and xefg_held_work (the work the held places
 *  did on the body: the kinetic energy their projections added). */
static int cohesive_history(const Sim *sim, void *state, FILE *f, int header)
{
    const Cohesive *c = state;
    if (header)
        return fprintf(f, ",cohesive_stored,cohesive_dissipated,"
                       "cohesive_traction,cohesive_opening,xefg_held_work") < 0
                   ? -1 : 0;
    double t, open;
    crack_means(c, &t, &open);
    return fprintf(f, ",%.9g,%.9g,%.9g,%.9g,%.9g", cohesive_stored_energy(c),
                   cohesive_dissipated_energy(c), t, open,
                   xefg_of(sim)->w_held) < 0 ? -1 : 0;
}
/// [cohesive_history]

/** The end of a run: the points and the energy balance of the XEFG run
 *  (stage 5's account follows the MPM step only). */
static int cohesive_report(const Sim *sim, void *state, FILE *f)
{
    const Cohesive *c = state;
    const Xefg *x = xefg_of(sim);
    const char *eu = sim->scene.run.units->energy;
    double k = xefg_kinetic_energy(x), u = xefg_strain_energy(x, sim);
    double s = cohesive_stored_energy(c), d = cohesive_dissipated_energy(c);
    double w = x->w_damped;
    double in = x->e0 + x->w_held, err = in - k - u - s - d - w;
    return fprintf(f, "mpm: cohesive: %d points; energy (%s) at t = %g: in %.9g "
                   "(start %.9g + held work %.9g) = kinetic %.9g + strain %.9g + "
                   "cohesive stored %.9g + dissipated %.9g + damped %.9g + error "
                   "%.9g (%+.4f %% of in)\n", c->npt, eu, sim->t, in, x->e0,
                   x->w_held, k, u, s, d, w, err,
                   in != 0.0 ? 100.0 * err / in : 0.0) < 0 ? -1 : 0;
}

/** The checkpoint: the history variables, the held and damped work. */
static int cohesive_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    Cohesive *c = state;
    Xefg *x = xefg_of(sim);
    int n = c->npt, m = c->npt;
    if (checkpoint_io(f, &m, sizeof m, save) || m != n ||
        checkpoint_io(f, c->dmax, sizeof(double) * (size_t)n, save) ||
        checkpoint_io(f, &x->w_held, sizeof x->w_held, save) ||
        checkpoint_io(f, &x->w_damped, sizeof x->w_damped, save) ||
        checkpoint_io(f, &x->e0, sizeof x->e0, save))
        return -1;
    if (!save)
        cohesive_force(c, x->u, NULL, 0);          /* tractions for output */
    return 0;
}

/** SEAM_ENERGY: the energy the cohesive law has dissipated. */
static double cohesive_energy(const Sim *sim, void *state, const char **name)
{
    (void)sim;
    *name = "cohesive";
    return cohesive_dissipated_energy(state);
}

int cohesive_subscribe(Sim *sim, Cohesive *c)
{
    Hooks *h = &sim->hooks;
    return hooks_on_history(h, cohesive_history, c) ||
           hooks_on_report(h, cohesive_report, c) ||
           hooks_on_checkpoint(h, cohesive_checkpoint, c) ||
           hooks_on_energy(h, cohesive_energy, c) ? -1 : 0;
}
