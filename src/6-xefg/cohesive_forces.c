/**
 * @file cohesive_forces.c
 * @brief The cohesive tractions as internal forces (the crack term of the
 *        weak form, Rabczuk and Zi eq. 22-30; xefg.md 2.1):
 *        f_q += int_Gamma_c [[psi_q]] t dGamma, the same traction pulling
 *        each face towards the other (equal and opposite), and the energy
 *        the law stores and dissipates.
 */
#include <math.h>

#include "cohesive.h"

/// [cohesive_force]
void cohesive_force(Cohesive *c, const double *u, double *f, int commit)
{
    const ShapeRows *J = &c->jump;
    for (int p = 0; p < c->npt; p++) {
        double jx = 0.0, jy = 0.0;                   /* [[u]] = u+ - u- */
        for (int e = J->start[p]; e < J->start[p + 1]; e++) {
            jx += J->N[e] * u[2 * J->dof[e]];
            jy += J->N[e] * u[2 * J->dof[e] + 1];
        }
        double tx = c->tx[p], ty = c->ty[p], nx = -ty, ny = tx;
        c->dn[p] = jx * nx + jy * ny;                /* opening, + apart */
        c->ds[p] = jx * tx + jy * ty;                /* sliding */
        CohesiveState s = cohesive_traction(&c->set[c->crack[p]].law, c->dn[p],
                                            c->ds[p], &c->dmax[p], commit);
        c->tn[p] = s.tn;
        c->ts[p] = s.ts;
        c->stored[p] = s.stored;
        if (!f)
            continue;
        /* the virtual work t . [[du]]: a traction that holds the faces
         * together is an internal force along the opening */
        double fx = c->w[p] * (s.tn * nx + s.ts * tx);
        double fy = c->w[p] * (s.tn * ny + s.ts * ty);
        for (int e = J->start[p]; e < J->start[p + 1]; e++) {
            f[2 * J->dof[e]] += J->N[e] * fx;
            f[2 * J->dof[e] + 1] += J->N[e] * fy;
        }
    }
}
/// [cohesive_force]

void cohesive_stiffness(const Cohesive *c, const double *z, double *kz)
{
    const ShapeRows *J = &c->jump;
    for (int p = 0; p < c->npt; p++) {
        const CohesiveLaw *L = &c->set[c->crack[p]].law;
        double jx = 0.0, jy = 0.0;
        for (int e = J->start[p]; e < J->start[p + 1]; e++) {
            jx += J->N[e] * z[2 * J->dof[e]];
            jy += J->N[e] * z[2 * J->dof[e] + 1];
        }
        double tx = c->tx[p], ty = c->ty[p], nx = -ty, ny = tx;
        double tn = L->K * (jx * nx + jy * ny);      /* the elastic branch */
        double ts = L->beta * L->beta * L->K * (jx * tx + jy * ty);
        double fx = c->w[p] * (tn * nx + ts * tx), fy = c->w[p] * (tn * ny + ts * ty);
        for (int e = J->start[p]; e < J->start[p + 1]; e++) {
            kz[2 * J->dof[e]] += J->N[e] * fx;
            kz[2 * J->dof[e] + 1] += J->N[e] * fy;
        }
    }
}

double cohesive_stored_energy(const Cohesive *c)
{
    double e = 0.0;
    for (int p = 0; p < c->npt; p++)
        e += c->w[p] * c->stored[p];
    return e;
}

double cohesive_dissipated_energy(const Cohesive *c)
{
    double e = 0.0;
    for (int p = 0; p < c->npt; p++)
        e += c->w[p] * cohesive_dissipated(&c->set[c->crack[p]].law, c->dmax[p]);
    return e;
}
