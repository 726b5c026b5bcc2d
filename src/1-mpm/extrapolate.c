/**
 * @file extrapolate.c
 * @brief Point to grid: masses, momenta, forces (and volumes) of every
 *        field slot (Tasks 1 and 3, eq. 8-9, 26 and 28).
 *
 * Each point writes only to the slots of its own stencil. On one thread the
 * loops visit the points in index order; on several, each thread owns a
 * strip of node rows (strips.h), visits the points that reach it in the
 * same order and adds only to its own nodes, through the same per-point
 * function: the same sums in the same order at every node.
 */
#include "step.h"
#include "strip_scatter.h"
#include "transfer.h"

void load_point_force(const Load *L, double t, double *fx, double *fy)
{
    double scale = ramp_factor(L->ramp, t);
    *fx = scale * L->fx / L->count;
    *fy = scale * L->fy / L->count;
}

/** Add the point loads of the scene, ramped in time, to the slot forces. */
static void add_point_loads(Sim *sim)
{
    const Scene *sc = &sim->scene;
    Grid *g = &sim->grid;
    for (int l = 0; l < sc->nloads; l++) {
        const Load *L = &sc->loads[l];
        if (L->count == 0)
            continue;
        double fx, fy;
        load_point_force(L, sim->t, &fx, &fy);
        for (int k = 0; k < L->count; k++) {
            Stencil st;
            int n = stencil_of_point(sim, L->points[k], &st);
            for (int a = 0; a < n; a++) {
                g->fx[st.slot[a]] += fx * st.S[a];
                g->fy[st.slot[a]] += fy * st.S[a];
            }
        }
    }
}

static void extrapolate_wide(Sim *sim, unsigned what);
static void extrapolate_strips(Sim *sim, unsigned what);

/// [extrapolate]
/** The momentum that one pair adds to slot @p s (eq. 26 and 31): the
 *  point's momentum (@p qx, @p qy) times S_ip; the one place to change
 *  for another transfer of momentum. */
static inline void momentum_pair(Grid *g, int s, double S, double qx,
                                 double qy)
{
    g->px[s] += qx * S;
    g->py[s] += qy * S;
}

/** One point's share of Tasks 1 and 3 over the @p n nodes of its stencil
 *  (those of @p own, or all): mass and momentum (eq. 26), or momentum
 *  only (eq. 31), and force (eq. 28), as @p what asks. Inlined at every
 *  call, so that a constant NULL @p own costs nothing. */
static inline __attribute__((always_inline)) void
scatter_point(const Particles *P, Grid *g, int p, const StencilRow *st, int n,
              unsigned what, const Owned *own)
{
    /* one loop for each case, so that the test is not made per node;
       S, Gx, Gy read once (a store to the grid could alias them), and
       the loops unrolled by the four corners */
    if (what & EXTRAP_MASS) {
        double mp = P->m[p], qx = mp * P->vx[p], qy = mp * P->vy[p];
#pragma GCC unroll 4
        for (int a = 0; a < n; a++) {
            int s = st->slot[a];
            double S = st->S[a];
            if (!owns(g, own, s))
                continue;
            g->m[s] += mp * S;                          /* eq. 26 */
            momentum_pair(g, s, S, qx, qy);
        }
    } else if (what & EXTRAP_MOMENTUM) {                /* eq. 31 */
        double mp = P->m[p], qx = mp * P->vx[p], qy = mp * P->vy[p];
#pragma GCC unroll 4
        for (int a = 0; a < n; a++) {
            int s = st->slot[a];
            if (!owns(g, own, s))
                continue;
            momentum_pair(g, s, st->S[a], qx, qy);
        }
    }
    if (what & EXTRAP_FORCE) {
        double v = P->vol[p];                           /* m_p / rho_p */
        double sxx = P->sxx[p], syy = P->syy[p], sxy = P->sxy[p];
#pragma GCC unroll 4
        for (int a = 0; a < n; a++) {                   /* eq. 28 */
            int s = st->slot[a];
            double Gx = st->Gx[a], Gy = st->Gy[a];
            if (!owns(g, own, s))
                continue;
            g->fx[s] -= v * (sxx * Gx + sxy * Gy);
            g->fy[s] -= v * (sxy * Gx + syy * Gy);
        }
    }
}

void extrapolate(Sim *sim, unsigned what)
{
    const Particles *P = &sim->pts;
    Grid *g = &sim->grid;
    if (sim->strips.n > 0)              /* several threads (strips.h) */
        extrapolate_strips(sim, what);
    else if (sim->scene.run.stencil)    /* another row of run.shape */
        extrapolate_wide(sim, what);
    else
        for (int p = 0; p < P->n; p++) {  /* the paper's four nodes */
            StencilRow st = stencil_stored(sim, p);
            scatter_point(P, g, p, &st, STENCIL_NODES, what, NULL);
        }
    if (what & EXTRAP_FORCE)            /* after every point, as on one */
        add_point_loads(sim);
}
/// [extrapolate]

/// [extrapolate_strips]
/** Strip @p t's scatters: its points in increasing index, through the
 *  stored bilinear stencil (@p wide 0, a constant after inlining) or the
 *  stored stencil of run.shape's function (@p wide 1) and run.transfer's
 *  term after each point's, as extrapolate_wide(); a point that reaches
 *  no other strip (most) needs no test of its pairs. */
static inline __attribute__((always_inline)) void
scatter_strip(Sim *sim, int t, unsigned what, int wide)
{
    const Particles *P = &sim->pts;
    const Strips *S = &sim->strips;
    Grid *g = &sim->grid;
    const Transfer *tr = wide && (what & (EXTRAP_MASS | EXTRAP_MOMENTUM))
                             ? sim->scene.run.transfer : NULL;
    Owned own = {S->first_node[t], S->first_node[t + 1]};
    for (int k = S->start[t]; k < S->start[t + 1]; k++) {
        int p = S->list[k], n = STENCIL_NODES;
        StencilRow st;
        if (wide) {
            st = stencil_row(stencil_stored_wide(sim, p));
            n = st.n;
        } else
            st = stencil_stored(sim, p);
        int edge = S->row_strips[S->code[p]] & 1;   /* at the strip's edge */
        if (edge)
            scatter_point(P, g, p, &st, n, what, &own);
        else
            scatter_point(P, g, p, &st, n, what, NULL);
        if (tr)                         /* run.transfer (chapter 8) */
            tr->scatter(sim, p, stencil_stored_wide(sim, p), g,
                        edge ? &own : NULL);
    }
}

/** The scatters on threads: strip t's thread visits the points that reach
 *  its nodes in increasing index (Task 0 listed them) and adds to its own
 *  nodes only, so that each node sums what it sums on one thread, in the
 *  same order. */
static void extrapolate_strips(Sim *sim, unsigned what)
{
    int wide = sim->scene.run.stencil != NULL;
#pragma omp parallel for num_threads(sim->threads) schedule(static, 1)
    for (int t = 0; t < sim->strips.n; t++) {
        if (wide)                       /* another row of run.shape */
            scatter_strip(sim, t, what, 1);
        else                            /* the paper's four nodes */
            scatter_strip(sim, t, what, 0);
    }
}
/// [extrapolate_strips]

/** The scatters through the stored stencils of run.shape's stencil
 *  function (chapter 8). */
static void extrapolate_wide(Sim *sim, unsigned what)
{
    const Particles *P = &sim->pts;
    Grid *g = &sim->grid;
    const Transfer *tr = sim->scene.run.transfer;
    for (int p = 0; p < P->n; p++) {
        const Stencil *w = stencil_stored_wide(sim, p);
        StencilRow st = stencil_row(w);
        scatter_point(P, g, p, &st, st.n, what, NULL);
        if (tr && (what & (EXTRAP_MASS | EXTRAP_MOMENTUM)))
            tr->scatter(sim, p, w, g, NULL);    /* run.transfer (chapter 8) */
    }
}
