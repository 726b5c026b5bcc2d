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
 *  largest normal opening), xefg_held_work (the work the held places
 *  did on the body: the impulses of their projections times the held
 *  velocities), xefg_damped_work (what the damping took out) and
 *  energy_error (the balance's, cohesive_energy_terms()). */
static int cohesive_history(const Sim *sim, void *state, FILE *f, int header)
{
    const Cohesive *c = state;
    if (header)
        return fprintf(f, ",cohesive_stored,cohesive_dissipated,"
                       "cohesive_traction,cohesive_opening,xefg_held_work,"
                       "xefg_damped_work,energy_error") < 0 ? -1 : 0;
    double t, open;
    crack_means(c, &t, &open);
    const Xefg *x = xefg_of(sim);
    return fprintf(f, ",%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g",
                   cohesive_stored_energy(c), cohesive_dissipated_energy(c), t,
                   open, x->w_held, x->w_damped,
                   cohesive_energy_terms(sim).error) < 0 ? -1 : 0;
}
/// [cohesive_history]

/// [cohesive_energy_terms]
EnergyTerms cohesive_energy_terms(const Sim *sim)
{
    const Xefg *x = xefg_of(sim);
    EnergyTerms e;
    e.in = x->e0 + x->w_held;
    e.stored = xefg_kinetic_energy(x) + xefg_strain_energy(x, sim) +
               cohesive_stored_energy(x->coh);
    e.damping = x->w_damped;
    e.dissipated = energy_seam_dissipated(sim);    /* the law's, by the seam */
    e.error = e.in - e.stored - e.damping - e.dissipated;
    return e;
}
/// [cohesive_energy_terms]

/** The end of a run: the points, what is stored, and the balance in stage
 *  5's line (whose own account follows the MPM step's seams only). */
static int cohesive_report(const Sim *sim, void *state, FILE *f)
{
    const Cohesive *c = state;
    const Xefg *x = xefg_of(sim);
    EnergyTerms e = cohesive_energy_terms(sim);
    if (fprintf(f, "mpm: cohesive: %d points; stored (%s) = kinetic %.9g + "
                "strain %.9g + cohesive %.9g\n", c->npt,
                sim->scene.run.units->energy, xefg_kinetic_energy(x),
                xefg_strain_energy(x, sim), cohesive_stored_energy(c)) < 0)
        return -1;
    return energy_terms_print(sim, &e, x->e0, 0, f);    /* held work counted */
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
