/**
 * @file growth_output.c
 * @brief What growth adds to a run's outputs: a history column and the
 *        events in the report (and, with max_speed, the steps waited) (the path itself is stage 2's crack, which
 *        the cracks_NNNNN series writes point by point).
 */
#include <stdio.h>

#include "growth.h"

/** history.csv: growth_segments, the segments added so far. */
static int growth_history(const Sim *sim, void *state, FILE *f, int header)
{
    (void)sim;
    const Growth *g = state;
    if (header)
        return fprintf(f, ",growth_segments") < 0 ? -1 : 0;
    return fprintf(f, ",%d", g->nevent) < 0 ? -1 : 0;
}

/** The end of a run: each crack's events and the last tip. */
static int growth_report(const Sim *sim, void *state, FILE *f)
{
    const Growth *g = state;
    const Xefg *x = xefg_of(sim);
    const char *tu = sim->scene.run.units->time;
    for (int k = 0; k < g->ncrack && k < x->ncrack; k++) {
        if (!g->set[k].on)
            continue;
        int n = 0, last = -1;
        for (int i = 0; i < g->nevent; i++)
            if (g->event[i].crack == k)
                n++, last = i;
        if (fprintf(f, "mpm: growth: crack %d grew %d of at most %d segments "
                    "of %g", k, n, g->set[k].max_segments, g->set[k].length) < 0)
            return -1;
        if (last >= 0 && fprintf(f, "; the last at t = %g %s to (%g, %g), "
                                 "sigma_1 %g", g->event[last].t, tu,
                                 g->event[last].x1, g->event[last].y1,
                                 g->event[last].sigma1) < 0)
            return -1;
        if (fprintf(f, "; %s; stable step %.6g %s (%d power iterations after "
                    "set-up)\n", x->crack[k].tip[0] || x->crack[k].tip[1] ?
                    "tips inside" : "through the body", x->stable_step, tu,
                    g->power_runs) < 0)
            return -1;
        if (g->set[k].max_speed > 0.0 &&
            fprintf(f, "mpm: growth: crack %d: max_speed %g %s/%s; steps a "
                    "tip (of any crack) waited for its max_speed: %ld\n", k,
                    g->set[k].max_speed, sim->scene.run.units->length, tu,
                    g->waits) < 0)
            return -1;
    }
    return 0;
}

int growth_subscribe(Sim *sim, Growth *g)
{
    Hooks *h = &sim->hooks;
    return hooks_on_history(h, growth_history, g) ||
           hooks_on_report(h, growth_report, g) ? -1 : 0;
}
