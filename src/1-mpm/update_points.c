/**
 * @file update_points.c
 * @brief Task 5: move the points with the grid solution (eq. 6 and 30).
 */
#include <math.h>

#include "shape.h"
#include "step.h"

/// [update_points]
int update_points(Sim *sim)
{
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    double dt = sim->dt;
    double xmax = g->ox + g->ncx * g->dx, ymax = g->oy + g->ncy * g->dy;
    for (int p = 0; p < P->n; p++) {
        double S[4], Gx[4], Gy[4];
        int n[4];
        pair_shape(sim, p, S, Gx, Gy, n);
        double ax = 0, ay = 0, vx = 0, vy = 0;
        for (int a = 0; a < 4; a++) {   /* each pair reads its own field */
            ax += S[a] * g->ax[n[a]];
            ay += S[a] * g->ay[n[a]];
            vx += S[a] * g->vx[n[a]];
            vy += S[a] * g->vy[n[a]];
        }
        P->vx[p] += dt * ax;
        P->vy[p] += dt * ay;
        P->x[p] += dt * vx;
        P->y[p] += dt * vy;
        if (!isfinite(P->vx[p]) || !isfinite(P->vy[p]))
            return step_fail(sim, p, isfinite(P->vx[p]) ? "velocity y" : "velocity x",
                        isfinite(P->vx[p]) ? P->vy[p] : P->vx[p]);
        if (!(P->x[p] >= g->ox && P->x[p] < xmax))
            return step_fail(sim, p, "position x (left the grid)", P->x[p]);
        if (!(P->y[p] >= g->oy && P->y[p] < ymax))
            return step_fail(sim, p, "position y (left the grid)", P->y[p]);
    }
    return 0;
}
/// [update_points]

