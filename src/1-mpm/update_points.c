/**
 * @file update_points.c
 * @brief Task 5: move the points with the grid solution (eq. 6 and 30).
 */
#include <math.h>

#include "step.h"
#include "transfer.h"

static int update_points_wide(Sim *sim, StencilFn wide);

/// [update_points]
/** Task 5 for point @p p over the @p n nodes of its stencil (eq. 30):
 *  0, or -1 with the instability recorded. */
static inline int move_point(Sim *sim, int p, const Stencil *st, int n,
                             double xmax, double ymax)
{
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    double dt = sim->dt, ax = 0, ay = 0, vx = 0, vy = 0;
    for (int a = 0; a < n; a++) {  /* each pair: its field */
        int s = st->slot[a];
        ax += st->S[a] * g->ax[s];
        ay += st->S[a] * g->ay[s];
        vx += st->S[a] * g->vx[s];
        vy += st->S[a] * g->vy[s];
    }
    P->vx[p] += dt * ax;
    P->vy[p] += dt * ay;
    P->x[p] += dt * vx;
    P->y[p] += dt * vy;
    /* record and go on: the loop has no early exit (threads) */
    if (!isfinite(P->vx[p]) || !isfinite(P->vy[p]))
        return step_fail(sim, p, isfinite(P->vx[p]) ? "velocity y" : "velocity x",
                         isfinite(P->vx[p]) ? P->vy[p] : P->vx[p]);
    else if (!(P->x[p] >= g->ox && P->x[p] < xmax))
        return step_fail(sim, p, "position x (left the grid)", P->x[p]);
    else if (!(P->y[p] >= g->oy && P->y[p] < ymax))
        return step_fail(sim, p, "position y (left the grid)", P->y[p]);
    return 0;
}

int update_points(Sim *sim)
{
    const Grid *g = &sim->grid;
    double xmax = g->ox + g->ncx * g->dx, ymax = g->oy + g->ncy * g->dy;
    int rc = 0, np = sim->pts.n;
    if (sim->scene.run.stencil)         /* another row of run.shape */
        return update_points_wide(sim, sim->scene.run.stencil);
    /* a point writes only its own arrays: any number of threads */
#pragma omp parallel for num_threads(sim->threads) reduction(min : rc)
    for (int p = 0; p < np; p++) {      /* the paper's four nodes */
        Stencil st;
        stencil_linear(sim, p, &st);
        if (move_point(sim, p, &st, STENCIL_NODES, xmax, ymax))
            rc = -1;
    }
    return rc;
}
/// [update_points]

/** Task 5 through a stencil of run.shape's table (chapter 8). */
static int update_points_wide(Sim *sim, StencilFn wide)
{
    const Grid *g = &sim->grid;
    double xmax = g->ox + g->ncx * g->dx, ymax = g->oy + g->ncy * g->dy;
    int rc = 0, np = sim->pts.n;
    const Transfer *tr = sim->scene.run.transfer;
    for (int p = 0; p < np; p++) {
        Stencil st;
        stencil_wide(sim, wide, p, &st);
        if (move_point(sim, p, &st, st.n, xmax, ymax))
            rc = -1;
        else if (tr)
            tr->gather(sim, p, &st);        /* run.transfer (chapter 8) */
    }
    return rc;
}
