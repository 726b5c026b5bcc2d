/**
 * @file xefg_forces.c
 * @brief The Galerkin sums over Gauss points: internal forces (eq. 30),
 *        strain and stress increments (small strain, P -> sigma), and the
 *        energies.
 */
#include <string.h>

#include "cohesive.h"
#include "xefg.h"
#include "xefg_gather.h"

/// [xefg_gauss_point]
/** Gauss point @p g: its strain increment from the parameters' increments
 *  @p du, grad du = sum du_q B_q, and its stress by its material's law
 *  (small strain, eq. 36 of chapter 1); the strain added to @p e (NULL:
 *  not kept). */
static inline void gauss_update(const Xefg *x, const Sim *sim, int g,
                                const double *du, double *s, double *e)
{
    const ShapeRows *R = &x->gauss;
    double uxx = 0.0, uxy = 0.0, uyx = 0.0, uyy = 0.0;
    for (int k = R->start[g]; k < R->start[g + 1]; k++) {
        int q = R->dof[k];
        uxx += du[2 * q] * R->Nx[k];
        uxy += du[2 * q] * R->Ny[k];
        uyx += du[2 * q + 1] * R->Nx[k];
        uyy += du[2 * q + 1] * R->Ny[k];
    }
    double dexy = 0.5 * (uxy + uyx);
    const Material *m = &sim->scene.mat[sim->pts.mat[x->gnode[g]]];
    m->law->stress(m, uxx, uyy, dexy, s);
    if (e) {
        e[0] += uxx;
        e[1] += uyy;
        e[2] += dexy;
    }
}

/** Gauss point @p g's share of the internal forces, f_q += w B_q^T sigma
 *  (eq. 30). */
static void gauss_scatter(const ShapeRows *R, int g, double w,
                          const double *s, double *f)
{
    double sxx = w * s[0], syy = w * s[1], sxy = w * s[2];
    for (int k = R->start[g]; k < R->start[g + 1]; k++) {
        int q = R->dof[k];
        f[2 * q] += sxx * R->Nx[k] + sxy * R->Ny[k];
        f[2 * q + 1] += sxy * R->Nx[k] + syy * R->Ny[k];
    }
}
/// [xefg_gauss_point]

void xefg_internal_force(const Xefg *x, const double *gs, double *f)
{
    memset(f, 0, 2 * sizeof(double) * (size_t)x->ndof);
    for (int g = 0; g < x->ngauss; g++)
        gauss_scatter(&x->gauss, g, x->gw[g], gs + 3 * g, f);
}

/// [xefg_threads]
void xefg_strain_update(const Xefg *x, const Sim *sim, const double *du,
                        double *gs, double *ge)
{
    /* each Gauss point writes its own stress and strain only: the same
       bits on any number of threads */
#pragma omp parallel for num_threads(sim->threads) schedule(static)
    for (int g = 0; g < x->ngauss; g++)
        gauss_update(x, sim, g, du, gs + 3 * g, ge ? ge + 3 * g : NULL);
}
/// [xefg_threads]

/// [xefg_update_and_force]
void xefg_update_and_force(const Xefg *x, const Sim *sim, const double *du,
                           double *f)
{
    if (xefg_gather_current(x)) {       /* one parallel region, two loops */
        double *ws = x->gather->ws;
#pragma omp parallel num_threads(sim->threads)
        {
#pragma omp for schedule(static)
            for (int g = 0; g < x->ngauss; g++) {   /* sigma, then w sigma */
                gauss_update(x, sim, g, du, x->gs + 3 * g, x->ge + 3 * g);
                for (int c = 0; c < 3; c++)
                    ws[3 * g + c] = x->gw[g] * x->gs[3 * g + c];
            }
            xefg_gather_force(x, f);                /* the same sums, turned */
        }
    } else {
        xefg_strain_update(x, sim, du, x->gs, x->ge);
        memset(f, 0, 2 * sizeof(double) * (size_t)x->ndof);
        for (int g = 0; g < x->ngauss; g++)         /* in order */
            gauss_scatter(&x->gauss, g, x->gw[g], x->gs + 3 * g, f);
    }
    if (x->coh)                                     /* the crack's tractions */
        cohesive_force(x->coh, x->u, f, 1);
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

/** Gauss point @p g's strain energy, w W(sigma, eps). */
static inline double strain_term(const Xefg *x, int g)
{
    const double *t = x->gs + 3 * g, *e = x->ge + 3 * g;
    return x->gw[g] * material_energy_density(t[0], t[1], t[2], e[0], e[1],
                                              e[2]);
}

double xefg_strain_energy(const Xefg *x, const Sim *sim)
{
    double s = 0.0;
    if (!x->gather) {                               /* one thread */
        for (int g = 0; g < x->ngauss; g++)
            s += strain_term(x, g);
        return s;
    }
    double *t = x->gather->ws;          /* the terms on the threads, */
#pragma omp parallel for num_threads(sim->threads) schedule(static)
    for (int g = 0; g < x->ngauss; g++)
        t[g] = strain_term(x, g);
    for (int g = 0; g < x->ngauss; g++)  /* summed in order: the same bits */
        s += t[g];
    return s;
}

void xefg_to_points(const Xefg *x, Sim *sim)
{
    Particles *P = &sim->pts;
    const ShapeRows *R = &x->at_node;
    int gather = xefg_gather_current(x);
#pragma omp parallel for if (gather) num_threads(sim->threads) schedule(static)
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
        if (gather) {                               /* cell average, turned */
            xefg_gather_cell(x, I, P);
            continue;
        }
        P->sxx[I] = P->syy[I] = P->sxy[I] = 0.0;
        P->exx[I] = P->eyy[I] = P->exy[I] = 0.0;
    }
    if (gather)
        return;
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
