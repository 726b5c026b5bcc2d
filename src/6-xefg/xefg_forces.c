/**
 * @file xefg_forces.c
 * @brief The Galerkin sums over Gauss points: internal forces (eq. 30),
 *        strain and stress increments (small strain, P -> sigma), and the
 *        energies.
 */
#include <string.h>

#include "xefg.h"

/// [xefg_internal_force]
void xefg_internal_force(const Xefg *x, const double *gs, double *f)
{
    const ShapeRows *R = &x->gauss;
    memset(f, 0, 2 * sizeof(double) * (size_t)x->ndof);
    for (int g = 0; g < x->ngauss; g++) {
        double w = x->gw[g];
        double sxx = w * gs[3 * g], syy = w * gs[3 * g + 1],
               sxy = w * gs[3 * g + 2];
        for (int e = R->start[g]; e < R->start[g + 1]; e++) {
            int q = R->dof[e];                       /* f_q = int B_q^T sigma */
            f[2 * q] += sxx * R->Nx[e] + sxy * R->Ny[e];
            f[2 * q + 1] += sxy * R->Nx[e] + syy * R->Ny[e];
        }
    }
}
/// [xefg_internal_force]

/// [xefg_strain_update]
void xefg_strain_update(const Xefg *x, const Sim *sim, const double *du,
                        double *gs, double *ge)
{
    const ShapeRows *R = &x->gauss;
    const Material *mats = sim->scene.mat;
    const int *mat = sim->pts.mat;
    for (int g = 0; g < x->ngauss; g++) {
        double uxx = 0.0, uxy = 0.0, uyx = 0.0, uyy = 0.0;
        for (int e = R->start[g]; e < R->start[g + 1]; e++) {
            int q = R->dof[e];                       /* grad du = sum du B */
            uxx += du[2 * q] * R->Nx[e];
            uxy += du[2 * q] * R->Ny[e];
            uyx += du[2 * q + 1] * R->Nx[e];
            uyy += du[2 * q + 1] * R->Ny[e];
        }
        double dexy = 0.5 * (uxy + uyx);
        const Material *m = &mats[mat[x->gnode[g]]];
        m->law->stress(m, uxx, uyy, dexy, gs + 3 * g);
        if (ge) {
            ge[3 * g] += uxx;
            ge[3 * g + 1] += uyy;
            ge[3 * g + 2] += dexy;
        }
    }
}
/// [xefg_strain_update]

/// [xefg_update_and_force]
void xefg_update_and_force(const Xefg *x, const Sim *sim, const double *du,
                           double *f)
{
    const ShapeRows *R = &x->gauss;
    const Material *mats = sim->scene.mat;
    const int *mat = sim->pts.mat;
    memset(f, 0, 2 * sizeof(double) * (size_t)x->ndof);
    for (int g = 0; g < x->ngauss; g++) {
        double uxx = 0.0, uxy = 0.0, uyx = 0.0, uyy = 0.0;
        for (int e = R->start[g]; e < R->start[g + 1]; e++) {
            int q = R->dof[e];                       /* grad du = sum du B */
            uxx += du[2 * q] * R->Nx[e];
            uxy += du[2 * q] * R->Ny[e];
            uyx += du[2 * q + 1] * R->Nx[e];
            uyy += du[2 * q + 1] * R->Ny[e];
        }
        double dexy = 0.5 * (uxy + uyx), *s = x->gs + 3 * g, *e = x->ge + 3 * g;
        const Material *m = &mats[mat[x->gnode[g]]];
        m->law->stress(m, uxx, uyy, dexy, s);        /* sigma += C d eps */
        e[0] += uxx;
        e[1] += uyy;
        e[2] += dexy;
        double w = x->gw[g], sxx = w * s[0], syy = w * s[1], sxy = w * s[2];
        for (int k = R->start[g]; k < R->start[g + 1]; k++) {
            int q = R->dof[k];                       /* f_q = int B_q^T sigma */
            f[2 * q] += sxx * R->Nx[k] + sxy * R->Ny[k];
            f[2 * q + 1] += sxy * R->Nx[k] + syy * R->Ny[k];
        }
    }
}
/// [xefg_update_and_force]

double xefg_kinetic_energy(const Xefg *x)
{
    double k = 0.0;
    for (int q = 0; q < x->ndof; q++)
        k += 0.5 * x->mass[q] *
             (x->v[2 * q] * x->v[2 * q] + x->v[2 * q + 1] * x->v[2 * q + 1]);
    return k;
}

double xefg_strain_energy(const Xefg *x, const Sim *sim)
{
    (void)sim;
    double s = 0.0;
    for (int g = 0; g < x->ngauss; g++) {
        const double *t = x->gs + 3 * g, *e = x->ge + 3 * g;
        s += x->gw[g] * material_energy_density(t[0], t[1], t[2], e[0], e[1],
                                                e[2]);
    }
    return s;
}

void xefg_to_points(const Xefg *x, Sim *sim)
{
    Particles *P = &sim->pts;
    const ShapeRows *R = &x->at_node;
    for (int I = 0; I < x->nnode; I++) {
        double ux = 0.0, uy = 0.0, vx = 0.0, vy = 0.0;
        for (int e = R->start[I]; e < R->start[I + 1]; e++) {
            int q = R->dof[e];                       /* u(X_I), eq. 1 */
            ux += R->N[e] * x->u[2 * q];
            uy += R->N[e] * x->u[2 * q + 1];
            vx += R->N[e] * x->v[2 * q];
            vy += R->N[e] * x->v[2 * q + 1];
        }
        P->x[I] = x->X[I] + ux;
        P->y[I] = x->Y[I] + uy;
        P->vx[I] = vx;
        P->vy[I] = vy;
        P->sxx[I] = P->syy[I] = P->sxy[I] = 0.0;
        P->exx[I] = P->eyy[I] = P->exy[I] = 0.0;
    }
    for (int g = 0; g < x->ngauss; g++) {          /* cell averages */
        int I = x->gnode[g];
        double w = x->gw[g] / x->cell_w[I];
        P->sxx[I] += w * x->gs[3 * g];
        P->syy[I] += w * x->gs[3 * g + 1];
        P->sxy[I] += w * x->gs[3 * g + 2];
        P->exx[I] += w * x->ge[3 * g];
        P->eyy[I] += w * x->ge[3 * g + 1];
        P->exy[I] += w * x->ge[3 * g + 2];
    }
}
