/**
 * @file growth_checkpoint.c
 * @brief A grown crack in a checkpoint: the growth events, replayed at
 *        restore. The checkpoint keeps the state, not the discretisation;
 *        the events' new tips, each inserted again by growth_insert() at
 *        its own step and time, rebuild the enrichment, quadrature,
 *        lumping, cohesive points and stable step as the run built them,
 *        and the sections that follow (the parameters', the cohesive
 *        points') load the state into them (chapter 6b, "A crack's speed
 *        and its restart").
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "checkpoint.h"
#include "cracks.h"
#include "growth.h"

/** Is event @p ev one that growth_after_step() could have written in a
 *  run of @p g that stands at step @p step, time @p t, after event
 *  @p prev (NULL: the first)? */
static int event_valid(const Growth *g, const Xefg *x, const GrowthEvent *ev,
                       const GrowthEvent *prev, long step, double t)
{
    return ev->crack >= 0 && ev->crack < g->ncrack && ev->crack < x->ncrack &&
           g->set[ev->crack].on && (ev->end == 0 || ev->end == 1) &&
           ev->step >= (prev ? prev->step : 0) && ev->step <= step &&
           ev->t >= (prev ? prev->t : 0.0) && ev->t <= t &&
           isfinite(ev->x1) && isfinite(ev->y1);
}

/** Stage 2's section, read before this one, gave each crack its grown
 *  points, in arrays of just that length: take the crack back to the
 *  points it was set up with (the grown ones at its ends, @p n events of
 *  @p ev, come off) in the room growth_build() reserved, which the
 *  parameters' line (CrackLine) points into again. @return 0 or -1. */
static int rewind_cracks(Sim *sim, Xefg *x, Growth *g, const GrowthEvent *ev,
                         int n)
{
    Cracks *C = cracks_of(sim);
    for (int k = 0; k < g->ncrack && k < x->ncrack; k++) {
        if (!g->set[k].on)
            continue;
        int grown[2] = {0, 0};
        for (int i = 0; i < n; i++)
            if (ev[i].crack == k && (ev[i].end == 0 || ev[i].end == 1))
                grown[ev[i].end]++;
        Crack *ck = &C->crack[k];
        int n0 = ck->n - grown[0] - grown[1];
        if (n0 < 2 || ck->n > g->point_cap[k] ||
            xefg_grow((void **)&ck->x, sizeof(double), g->point_cap[k]) ||
            xefg_grow((void **)&ck->y, sizeof(double), g->point_cap[k]))
            return -1;
        memmove(ck->x, ck->x + grown[0], sizeof(double) * (size_t)n0);
        memmove(ck->y, ck->y + grown[0], sizeof(double) * (size_t)n0);
        ck->n = n0;
        crack_extent(ck);
        x->crack[k].x = ck->x;
        x->crack[k].y = ck->y;
        x->crack[k].n = n0;
    }
    return 0;
}

/** Insert the @p n events of @p ev again, each at its own step and time
 *  (growth_insert() lowers the run's step from them, as it did), into the
 *  discretisation as set up. @return 0, or -1 when an event does not
 *  start at its crack's tip or the insertion fails (message on stderr). */
static int replay(Sim *sim, Xefg *x, Growth *g, const GrowthEvent *ev, int n)
{
    long step = sim->step;
    double t = sim->t;
    int rc = 0;
    for (int i = 0; i < n && rc == 0; i++) {
        const GrowthEvent *e = &ev[i];
        double tip[2], dir[2];
        crack_line_tip(&x->crack[e->crack], e->end, tip, dir);
        if (!event_valid(g, x, e, i ? &ev[i - 1] : NULL, step, t) ||
            !x->crack[e->crack].tip[e->end] || tip[0] != e->x0 ||
            tip[1] != e->y0) {
            fprintf(stderr, "mpm: growth: event %d of the checkpoint does not "
                    "continue crack %d's tip\n", i, e->crack);
            rc = -1;
            break;
        }
        sim->step = e->step;
        sim->t = e->t;
        rc = growth_insert(sim, x, g, e->crack, e->end, e->x1, e->y1, g->msg,
                           sizeof g->msg);
        if (rc)
            fprintf(stderr, "mpm: growth: event %d of the checkpoint: %s\n", i,
                    g->msg);
        else
            g->nevent = i + 1;   /* event i is in place (ev may be g->event) */
    }
    sim->step = step;
    sim->t = t;
    return rc;
}

/// [growth_checkpoint]
int growth_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    Growth *g = state;
    Xefg *x = xefg_of(sim);
    int n = g->nevent;
    if (!x || x->grow != g ||
        checkpoint_io(f, &n, sizeof n, save) ||
        checkpoint_io(f, &g->waits, sizeof g->waits, save))
        return -1;
    if (save)
        return checkpoint_io(f, g->event, sizeof(GrowthEvent) * (size_t)n, 1);
    /* restore: a discretisation as set up takes the events once */
    if (g->nevent != 0 || n < 0 || n > g->event_cap ||
        checkpoint_io(f, g->event, sizeof(GrowthEvent) * (size_t)n, 0))
        return -1;
    return rewind_cracks(sim, x, g, g->event, n) ||
           replay(sim, x, g, g->event, n) ? -1 : 0;
}
/// [growth_checkpoint]
