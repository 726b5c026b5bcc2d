/**
 * @file stress_update.c
 * @brief Strain increments from the nodal velocities and the stress update
 *        by each material's law (Appendix, "Updating Stresses and
 *        Strains", eq. 34-36).
 */
#include <math.h>

#include "step.h"

/// [rotate_with_spin]
/** Rotate the symmetric tensor (t[0], t[1], t[2]) = (xx, yy, xy) by the
 *  rotation whose cosine is @p c and sine @p s: t <- R t R^T. */
static void rotate_by(double c, double s, double t[3])
{
    double xx = t[0], yy = t[1], xy = t[2];
    t[0] = c * c * xx - 2.0 * c * s * xy + s * s * yy;
    t[1] = s * s * xx + 2.0 * c * s * xy + c * c * yy;
    t[2] = c * s * (xx - yy) + (c * c - s * s) * xy;
}

/** Turn point @p p's stress and strain by the spin of the nodal velocities
 *  over the @p n nodes of its stencil, w = 1/2 (v,x - u,y) dt, by the
 *  rotation (I - W/2)^-1 (I + W/2) (angle 2 atan(w/2)). */
static inline void rotate_point(Sim *sim, int p, const StencilRow *st, int n,
                                double dt_star)
{
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    double spin = 0.0;
    for (int a = 0; a < n; a++)
        spin += g->vy[st->slot[a]] * st->Gx[a] - g->vx[st->slot[a]] * st->Gy[a];
    double h = 0.25 * dt_star * spin, d = 1.0 / (1.0 + h * h);
    double c = (1.0 - h * h) * d, sn = 2.0 * h * d;
    double s[3] = {P->sxx[p], P->syy[p], P->sxy[p]};
    double e[3] = {P->exx[p], P->eyy[p], P->exy[p]};
    rotate_by(c, sn, s);
    rotate_by(c, sn, e);
    P->sxx[p] = s[0];
    P->syy[p] = s[1];
    P->sxy[p] = s[2];
    P->exx[p] = e[0];
    P->eyy[p] = e[1];
    P->exy[p] = e[2];
}

/** The objective rate (run.stress_rate = "jaumann"): turn each point's
 *  stress and strain with the spin of the same nodal velocities that give
 *  its strain increment. A pass of its own, so that the paper's update
 *  costs nothing more. */
static void rotate_with_spin(Sim *sim, double dt_star)
{
    if (!sim->scene.run.stencil)        /* the paper's four nodes */
        for (int p = 0; p < sim->pts.n; p++) {
            StencilRow st = stencil_stored(sim, p);
            rotate_point(sim, p, &st, STENCIL_NODES, dt_star);
        }
    else                                /* another row of run.shape */
        for (int p = 0; p < sim->pts.n; p++) {
            StencilRow st = stencil_row(stencil_stored_wide(sim, p));
            rotate_point(sim, p, &st, st.n, dt_star);
        }
}
/// [rotate_with_spin]

static int update_stress_wide(Sim *sim, double dt_star);

/// [update_stress]
/** Point @p p's strain increment from the nodal velocities over the @p n
 *  nodes of its stencil (eq. 34-35) and its material's stress update
 *  (eq. 36): 0, or -1 with a non-finite stress recorded. */
static inline int strain_point(Sim *sim, int p, const StencilRow *st, int n,
                               double dt_star)
{
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    double L[4];                        /* du/dx, du/dy, dv/dx, dv/dy */
    row_velocity_gradient(g, st, n, L);
    double dexx = dt_star * L[0], deyy = dt_star * L[3];
    double dexy = 0.5 * dt_star * (L[1] + L[2]);        /* eq. 35 */
    P->exx[p] += dexx;
    P->eyy[p] += deyy;
    P->exy[p] += dexy;
    const Material *mat = &sim->scene.mat[P->mat[p]];
    double s[3] = {P->sxx[p], P->syy[p], P->sxy[p]};
    mat->law->stress(mat, dexx, deyy, dexy, s);         /* eq. 36 */
    P->sxx[p] = s[0];
    P->syy[p] = s[1];
    P->sxy[p] = s[2];
    if (!isfinite(s[0] + s[1] + s[2]))
        return step_fail(sim, p, "stress",
                         !isfinite(s[0]) ? s[0] : !isfinite(s[1]) ? s[1] : s[2]);
    return 0;
}

int update_stress(Sim *sim, double dt_star)
{
    int rc = 0;
    if (sim->scene.run.objective)
        rotate_with_spin(sim, dt_star);
    if (sim->scene.run.stencil)         /* another row of run.shape */
        return update_stress_wide(sim, dt_star);
    /* a point writes only its own arrays: any number of threads */
#pragma omp parallel for num_threads(sim->threads) reduction(min : rc)
    for (int p = 0; p < sim->pts.n; p++) {  /* the paper's four nodes */
        StencilRow st = stencil_stored(sim, p);
        if (strain_point(sim, p, &st, STENCIL_NODES, dt_star))
            rc = -1;
    }
    return rc;
}
/// [update_stress]

/** The strain and stress through the stored stencils of run.shape's
 *  stencil function (chapter 8). */
static int update_stress_wide(Sim *sim, double dt_star)
{
    int rc = 0;
#pragma omp parallel for num_threads(sim->threads) reduction(min : rc)
    for (int p = 0; p < sim->pts.n; p++) {
        StencilRow st = stencil_row(stencil_stored_wide(sim, p));
        if (strain_point(sim, p, &st, st.n, dt_star))
            rc = -1;
    }
    return rc;
}
