/**
 * @file growth_cohesive.c
 * @brief The cohesive points a new segment brings (xefg.md 2.3, traction
 *        continuity): they start closed, with the history of a point that
 *        never opened (delta_max = 0, on the penalty branch), and the jump
 *        rows of the old points near the segment, which gain the new
 *        parameters.
 */
#include <math.h>

#include "cohesive.h"
#include "growth.h"

/** The first body holding (px, py) (edges included), or -1. */
static int body_at(const Scene *sc, double px, double py)
{
    for (int b = 0; b < sc->nbodies; b++)
        if (shape_contains(&sc->bodies[b].shape, px, py))
            return b;
    return -1;
}

/** The jump row of point @p p, appended to Growth::rows. @return 0 or -1. */
static int jump_row(const Sim *sim, const Xefg *x, Growth *g, const Cohesive *C,
                    int p)
{
    ShapeRows *R = &g->row, *S = &g->rows;
    int b = body_at(&sim->scene, C->px[p], C->py[p]);
    R->n = R->len = 0;
    if (b < 0 || xefg_shape_row(x, &g->cl, sim->pts.body, b, C->px[p], C->py[p],
                                0, R))
        return -1;
    int n = cohesive_jump_row(x, R, C->crack[p], C->px[p], C->py[p], NULL, NULL);
    if (S->n + 1 > S->ncap || S->cap - S->len < n || shape_rows_add(S, n, 0))
        return -1;
    int j = S->start[S->n - 1];
    cohesive_jump_row(x, R, C->crack[p], C->px[p], C->py[p], S->dof + j, S->N + j);
    return 0;
}

/// [growth_cohesive]
int growth_cohesive(Sim *sim, Xefg *x, Growth *g, int c, int seg,
                    const double a[2], const double b[2], char *err,
                    size_t errlen)
{
    Cohesive *C = x->coh;
    ShapeRows *J = &C->jump, *S = &g->rows;
    double dmax = 0.0;
    for (int I = 0; I < x->nnode; I++)
        dmax = fmax(dmax, x->d[I]);
    double reach = 2.0 * dmax * (1.0 + 1e-9);
    S->n = S->len = 0;
    for (int p = 0; p < C->npt; p++) {       /* old points near it */
        g->mark[p] = -1;
        g->len[p] = J->start[p + 1] - J->start[p];
        if (C->crack[p] != c ||
            growth_segment_distance(a, b, C->px[p], C->py[p]) >= reach)
            continue;
        if (jump_row(sim, x, g, C, p))
            goto full;
        g->mark[p] = S->n - 1;
        g->len[p] = S->start[S->n] - S->start[S->n - 1];
    }
    if (growth_rows_expand(J, g->len, 0))
        goto full;
    for (int p = 0; p < C->npt; p++)
        if (g->mark[p] >= 0)
            growth_copy_row(J, p, S, g->mark[p]);
    /* the new segment's points: room for a piece per spacing and one more */
    double len = hypot(b[0] - a[0], b[1] - a[1]);
    int more = ((int)ceil(len / g->h) + 1) * x->set.gauss, n0 = C->npt;
    if (C->npt + more > g->coh_cap || J->n + more > J->ncap ||
        J->cap - J->len < more * ROW_ROOM / 8)
        goto full;
    int cap = g->coh_cap;
    g->row.n = g->row.len = 0;
    if (cohesive_segment_points(C, x, sim, &g->cl, c, seg, g->h, &g->row, &cap,
                                err, errlen))
        return -1;
    for (int p = n0; p < C->npt; p++)     /* closed, never opened: t = 0 */
        C->dmax[p] = C->dn[p] = C->ds[p] = C->tn[p] = C->ts[p] =
            C->stored[p] = 0.0;
    return 0;
full:
    snprintf(err, errlen, "growth of crack %d stopped: the cohesive points "
             "reserved at set-up are full", c);
    return -1;
}
/// [growth_cohesive]
