/**
 * @file stress_update.c
 * @brief Strain increments from the nodal velocities and the elastic
 *        stress update (Appendix, "Updating Stresses and Strains",
 *        eq. 34-36).
 */
#include <math.h>

#include "shape.h"
#include "step.h"

/// [update_stress]
int update_stress(Sim *sim, double dt_star)
{
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    const Material *mats = sim->scene.mat;
    for (int p = 0; p < P->n; p++) {
        double S[4], Gx[4], Gy[4];
        int n[4];
        pair_shape(sim, p, S, Gx, Gy, n);
        double dudx = 0, dudy = 0, dvdx = 0, dvdy = 0;
        for (int a = 0; a < 4; a++) {   /* L_p = sum_i v_i (outer) G_ip */
            dudx += g->vx[n[a]] * Gx[a];
            dudy += g->vx[n[a]] * Gy[a];
            dvdx += g->vy[n[a]] * Gx[a];
            dvdy += g->vy[n[a]] * Gy[a];
        }
        double dexx = dt_star * dudx, deyy = dt_star * dvdy;
        double dexy = 0.5 * dt_star * (dudy + dvdx);    /* eq. 35 */
        P->exx[p] += dexx;
        P->eyy[p] += deyy;
        P->exy[p] += dexy;
        double s[3] = {P->sxx[p], P->syy[p], P->sxy[p]};
        elastic_stress_increment(&mats[P->mat[p]], dexx, deyy, dexy, s);
        P->sxx[p] = s[0];
        P->syy[p] = s[1];
        P->sxy[p] = s[2];
        if (!isfinite(s[0] + s[1] + s[2]))
            return step_fail(sim, p, "stress",
                             !isfinite(s[0]) ? s[0] : !isfinite(s[1]) ? s[1] : s[2]);
    }
    return 0;
}
/// [update_stress]
