/**
 * @file extrapolate.c
 * @brief Point to grid: masses, momenta and forces of every field slot
 *        (Tasks 1 and 3, eq. 26 and 28).
 */
#include <math.h>

#include "shape.h"
#include "step.h"

/** Add the point loads of the scene, ramped in time, to the slot forces. */
static void add_point_loads(Sim *sim)
{
    const Scene *sc = &sim->scene;
    Grid *g = &sim->grid;
    for (int l = 0; l < sc->nloads; l++) {
        const Load *L = &sc->loads[l];
        if (L->count == 0)
            continue;
        double scale = (L->ramp > 0.0 && sim->t < L->ramp) ? sim->t / L->ramp : 1.0;
        double fx = scale * L->fx / L->count, fy = scale * L->fy / L->count;
        for (int k = 0; k < L->count; k++) {
            int p = L->points[k], n[4];
            double S[4], Gx[4], Gy[4];
            pair_shape(sim, p, S, Gx, Gy, n);
            for (int a = 0; a < 4; a++) {
                g->fx[n[a]] += fx * S[a];
                g->fy[n[a]] += fy * S[a];
            }
        }
    }
}

/// [extrapolate]
void extrapolate(Sim *sim, unsigned what)
{
    const Particles *P = &sim->pts;
    Grid *g = &sim->grid;
    for (int p = 0; p < P->n; p++) {
        double S[4], Gx[4], Gy[4];
        int n[4];
        pair_shape(sim, p, S, Gx, Gy, n);
        if (what & (EXTRAP_MASS | EXTRAP_MOMENTUM)) {
            double mp = P->m[p], qx = mp * P->vx[p], qy = mp * P->vy[p];
            for (int a = 0; a < 4; a++) {
                if (what & EXTRAP_MASS)
                    g->m[n[a]] += mp * S[a];            /* eq. 26 */
                g->px[n[a]] += qx * S[a];
                g->py[n[a]] += qy * S[a];
            }
        }
        if (what & EXTRAP_FORCE) {
            double v = P->vol[p];                       /* m_p / rho_p */
            double sxx = P->sxx[p], syy = P->syy[p], sxy = P->sxy[p];
            for (int a = 0; a < 4; a++) {               /* eq. 28 */
                g->fx[n[a]] -= v * (sxx * Gx[a] + sxy * Gy[a]);
                g->fy[n[a]] -= v * (sxy * Gx[a] + syy * Gy[a]);
            }
        }
    }
    if (what & EXTRAP_FORCE)
        add_point_loads(sim);
}
/// [extrapolate]
