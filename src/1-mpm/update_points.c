/**
 * @file update_points.c
 * @brief Task 5: move the points with the grid solution (eq. 6 and 30).
 */
#include <math.h>

#include "step.h"
#include "transfer.h"

static int update_points_wide(Sim *sim);

/// [update_points]
/** Task 5 for point @p p over the @p n nodes of its stencil (eq. 30):
 *  0, or -1 with the instability recorded. */
static inline int move_point(Sim *sim, int p, const StencilRow *st, int n,
                             double xmax, double ymax)
{
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    double dt = sim->dt, ax = 0, ay = 0, vx = 0, vy = 0;
#pragma GCC unroll 4
    for (int a = 0; a < n; a++) {  /* each pair: its field */
        int s = st->slot[a];
        double S = st->S[a];
        ax += S * g->ax[s];
        ay += S * g->ay[s];
        vx += S * g->vx[s];
        vy += S * g->vy[s];
    }
    double u = P->vx[p] + dt * ax, v = P->vy[p] + dt * ay;
    double x = P->x[p] + dt * vx, y = P->y[p] + dt * vy;
    P->vx[p] = u;
    P->vy[p] = v;
    P->x[p] = x;
    P->y[p] = y;
    /* record and go on: the loop has no early exit (threads) */
    if (!isfinite(u) || !isfinite(v))
        return step_fail(sim, p, isfinite(u) ? "velocity y" : "velocity x",
                         isfinite(u) ? v : u);
    else if (!(x >= g->ox && x < xmax))
        return step_fail(sim, p, "position x (left the grid)", x);
    else if (!(y >= g->oy && y < ymax))
        return step_fail(sim, p, "position y (left the grid)", y);
    return 0;
}

int update_points(Sim *sim)
{
    const Grid *g = &sim->grid;
    double xmax = g->ox + g->ncx * g->dx, ymax = g->oy + g->ncy * g->dy;
    int rc = 0, np = sim->pts.n;
    if (sim->scene.run.stencil)         /* another row of run.shape */
        return update_points_wide(sim);
    /* a point writes only its own arrays: any number of threads */
#pragma omp parallel for num_threads(sim->threads) reduction(min : rc)
    for (int p = 0; p < np; p++) {      /* the paper's four nodes */
        StencilRow st = stencil_stored(sim, p);
        if (move_point(sim, p, &st, STENCIL_NODES, xmax, ymax))
            rc = -1;
    }
    return rc;
}
/// [update_points]

/** Task 5 through the stored stencils of run.shape's stencil function
 *  (chapter 8). */
static int update_points_wide(Sim *sim)
{
    const Grid *g = &sim->grid;
    double xmax = g->ox + g->ncx * g->dx, ymax = g->oy + g->ncy * g->dy;
    int rc = 0, np = sim->pts.n;
    const Transfer *tr = sim->scene.run.transfer;
    /* a point writes only its own arrays (the gather too) */
#pragma omp parallel for num_threads(sim->threads) reduction(min : rc)
    for (int p = 0; p < np; p++) {
        const Stencil *w = stencil_stored_wide(sim, p);
        StencilRow st = stencil_row(w);
        if (move_point(sim, p, &st, st.n, xmax, ymax))
            rc = -1;
        else if (tr)
            tr->gather(sim, p, w);          /* run.transfer (chapter 8) */
    }
    return rc;
}
