/**
 * @file stress_update.c
 * @brief Strain increments from the nodal velocities and the stress update
 *        by each material's law (Appendix, "Updating Stresses and
 *        Strains", eq. 34-36).
 */
#include <math.h>

#include "step.h"

/// [update_stress]
int update_stress(Sim *sim, double dt_star)
{
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    const Material *mats = sim->scene.mat;
    int rc = 0;
    for (int p = 0; p < P->n; p++) {
        Stencil st;
        stencil_of_point(sim, p, &st);
        double dudx = 0, dudy = 0, dvdx = 0, dvdy = 0;
        for (int a = 0; a < STENCIL_NODES; a++) {  /* L_p = sum v_i (x) G_ip */
            int s = st.slot[a];
            dudx += g->vx[s] * st.Gx[a];
            dudy += g->vx[s] * st.Gy[a];
            dvdx += g->vy[s] * st.Gx[a];
            dvdy += g->vy[s] * st.Gy[a];
        }
        double dexx = dt_star * dudx, deyy = dt_star * dvdy;
        double dexy = 0.5 * dt_star * (dudy + dvdx);    /* eq. 35 */
        P->exx[p] += dexx;
        P->eyy[p] += deyy;
        P->exy[p] += dexy;
        const Material *mat = &mats[P->mat[p]];
        double s[3] = {P->sxx[p], P->syy[p], P->sxy[p]};
        mat->law->stress(mat, dexx, deyy, dexy, s);     /* eq. 36 */
        P->sxx[p] = s[0];
        P->syy[p] = s[1];
        P->sxy[p] = s[2];
        if (!isfinite(s[0] + s[1] + s[2]))
            rc = step_fail(sim, p, "stress",
                           !isfinite(s[0]) ? s[0] : !isfinite(s[1]) ? s[1] : s[2]);
    }
    return rc;
}
/// [update_stress]
