/**
 * @file j_integral_output.c
 * @brief When J is evaluated (Task 7, every few steps), and where it is
 *        written: history.csv's columns, the end-of-run report and the
 *        checkpoint.
 */
#include <math.h>
#include <string.h>

#include "checkpoint.h"
#include "crack_growth.h"
#include "j_integral.h"
#include "step.h"

/// [j_integral_task7]
int j_integral_task7(Sim *sim, void *state, Seam seam)
{
    JState *S = state;
    (void)seam;
    long done = sim->step + 1;           /* steps taken at the end of this one */
    if (done % S->every != 0 && done != sim->nsteps)
        return 0;
    if (j_integral_evaluate(sim, S)) {
        sim->fail = (Failure){sim->step, sim->t, -1, "j-integral memory", NAN, 0};
        return -1;
    }
    S->at_step = done;
    S->at_time = sim->t + sim->dt;
    /* growth acts on a fresh J only (cracks.[k].growth) */
    CrackGrowth *G = sim_state(sim, "crack-growth");
    return G ? crack_growth_step(sim, G, S) : 0;
}
/// [j_integral_task7]

int j_integral_history(const Sim *sim, void *state, FILE *f, int header)
{
    const JState *S = state;
    (void)sim;
    for (int t = 0; t < S->ntips; t++) {
        const JTip *T = &S->tip[t];
        const JSettings *j = &S->set[T->crack];
        const char *name[3] = {"J", "KI", "KII"};
        const double *val[3] = {T->J, T->KI, T->KII};
        for (int k = 0; k < 3; k++)
            for (int m = 0; m < j->ncontours; m++) {
                int rc = header ? fprintf(f, ",%s_crack%d_%s_c%d", name[k],
                                          T->crack, T->end ? "last" : "first",
                                          j->contour[m])
                                : fprintf(f, ",%.9g", val[k][m]);
                if (rc < 0)
                    return -1;
            }
    }
    return 0;
}

int j_integral_report(const Sim *sim, void *state, FILE *f)
{
    const JState *S = state;
    const Units *u = sim->scene.run.units;
    for (int t = 0; t < S->ntips; t++) {
        const JTip *T = &S->tip[t];
        const JSettings *j = &S->set[T->crack];
        double lo = T->J[0], hi = T->J[0];
        if (fprintf(f, "mpm: J-integral at t = %g %s (step %ld), crack %d, "
                    "%s point (%.6g, %.6g):", S->at_time, u->time, S->at_step,
                    T->crack, T->end ? "last" : "first", T->x, T->y) < 0)
            return -1;
        for (int m = 0; m < j->ncontours; m++) {
            lo = fmin(lo, T->J[m]);
            hi = fmax(hi, T->J[m]);
            if (fprintf(f, " %d cells %.6g%s", j->contour[m], T->J[m],
                        m + 1 < j->ncontours ? "," : "") < 0)
                return -1;
        }
        double mid = 0.5 * (lo + hi);
        if (fprintf(f, " %s/%s^2; spread %.3g %%\n", u->energy, u->length,
                    mid != 0.0 ? 100.0 * (hi - lo) / fabs(mid) : 0.0) < 0)
            return -1;
        if (fprintf(f, "mpm: K_I, K_II (interaction integral), crack %d, %s "
                    "point:", T->crack, T->end ? "last" : "first") < 0)
            return -1;
        for (int m = 0; m < j->ncontours; m++)
            if (fprintf(f, " %d cells %.6g, %.6g%s", j->contour[m], T->KI[m],
                        T->KII[m], m + 1 < j->ncontours ? ";" : "") < 0)
                return -1;
        if (fprintf(f, " %s %s^1/2\n", u->stress, u->length) < 0)
            return -1;
    }
    return 0;
}

/// [j_integral_checkpoint]
int j_integral_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    JState *S = state;
    int n = S->npoints, m = n;
    if (checkpoint_io(f, &m, sizeof m, save) || m != n ||
        checkpoint_io(f, S->X, sizeof(double) * (size_t)n, save) ||
        checkpoint_io(f, S->Y, sizeof(double) * (size_t)n, save) ||
        checkpoint_io(f, &S->at_step, sizeof S->at_step, save) ||
        checkpoint_io(f, &S->at_time, sizeof S->at_time, save))
        return -1;
    for (int t = 0; t < S->ntips; t++)
        if (checkpoint_io(f, S->tip[t].J, sizeof S->tip[t].J, save) ||
            checkpoint_io(f, S->tip[t].KI, sizeof S->tip[t].KI, save) ||
            checkpoint_io(f, S->tip[t].KII, sizeof S->tip[t].KII, save))
            return -1;
    if (!save)
        j_integral_tips(sim, S);
    return 0;
}
/// [j_integral_checkpoint]
