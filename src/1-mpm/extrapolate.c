/**
 * @file extrapolate.c
 * @brief Point to grid: masses, momenta, forces (and volumes) of every
 *        field slot (Tasks 1 and 3, eq. 8-9, 26 and 28).
 *
 * Each point writes only to the slots of its own stencil. The loops visit
 * points in index order; a threaded loop will visit points binned by cell
 * with the cells coloured so that no two threads share a node, and call
 * the same per-point functions.
 */
#include "step.h"
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

static void extrapolate_wide(Sim *sim, StencilFn wide, unsigned what);

/// [extrapolate]
/** One point's share of Tasks 1 and 3 over the @p n nodes of its stencil:
 *  mass and momentum (eq. 26), or momentum only (eq. 31), and force
 *  (eq. 28), as @p what asks. */
static inline void scatter_point(const Particles *P, Grid *g, int p,
                                 const Stencil *st, int n, unsigned what)
{
    /* one loop for each case, so that the test is not made per node */
    if (what & EXTRAP_MASS) {
        double mp = P->m[p], qx = mp * P->vx[p], qy = mp * P->vy[p];
        for (int a = 0; a < n; a++) {
            int s = st->slot[a];
            g->m[s] += mp * st->S[a];                   /* eq. 26 */
            g->px[s] += qx * st->S[a];
            g->py[s] += qy * st->S[a];
        }
    } else if (what & EXTRAP_MOMENTUM) {                /* eq. 31 */
        double mp = P->m[p], qx = mp * P->vx[p], qy = mp * P->vy[p];
        for (int a = 0; a < n; a++) {
            int s = st->slot[a];
            g->px[s] += qx * st->S[a];
            g->py[s] += qy * st->S[a];
        }
    }
    if (what & EXTRAP_FORCE) {
        double v = P->vol[p];                           /* m_p / rho_p */
        double sxx = P->sxx[p], syy = P->syy[p], sxy = P->sxy[p];
        for (int a = 0; a < n; a++) {                   /* eq. 28 */
            int s = st->slot[a];
            g->fx[s] -= v * (sxx * st->Gx[a] + sxy * st->Gy[a]);
            g->fy[s] -= v * (sxy * st->Gx[a] + syy * st->Gy[a]);
        }
    }
}

void extrapolate(Sim *sim, unsigned what)
{
    const Particles *P = &sim->pts;
    Grid *g = &sim->grid;
    if (sim->scene.run.stencil)         /* another row of run.shape */
        extrapolate_wide(sim, sim->scene.run.stencil, what);
    else
        for (int p = 0; p < P->n; p++) {  /* the paper's four nodes */
            Stencil st;
            stencil_linear(sim, p, &st);
            scatter_point(P, g, p, &st, STENCIL_NODES, what);
        }
    if (what & EXTRAP_FORCE)
        add_point_loads(sim);
}
/// [extrapolate]

/** The scatters through a stencil of run.shape's table (chapter 8). */
static void extrapolate_wide(Sim *sim, StencilFn wide, unsigned what)
{
    const Particles *P = &sim->pts;
    Grid *g = &sim->grid;
    const Transfer *tr = sim->scene.run.transfer;
    for (int p = 0; p < P->n; p++) {
        Stencil st;
        wide(sim, p, &st);
        scatter_point(P, g, p, &st, st.n, what);
        if (tr && (what & (EXTRAP_MASS | EXTRAP_MOMENTUM)))
            tr->scatter(sim, p, &st, g);    /* run.transfer (chapter 8) */
    }
}
